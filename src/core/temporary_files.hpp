// The temporary files being written right now, for a second Ctrl-C to remove.
// The first Ctrl-C is a request (interrupt.hpp): the job stops, its
// AtomicFiles unwind and remove their temporary files. A second one ends the
// process at once, without unwinding; the signal handler then removes the
// files listed here before the process goes, so that none stays behind.
#pragma once

#include <filesystem>

namespace lbmshape::temporary_files {

// Lists `path`; returns a ticket for forget(), or -1 when the list is full
// or the path too long (the file is then only removed by its owner).
// Thread-safe. A folder may be listed too: it is removed only if empty (a
// morph's output folder, until its first frame is written).
int remember(const std::filesystem::path& path);
// Takes the file off the list (it was renamed or removed). Thread-safe.
void forget(int ticket);

// Removes every listed file (and every listed folder that is empty).
// Async-signal-safe: for a signal handler, or for a process that ends
// without unwinding (core/last_resort.hpp).
void removeAllFromSignalHandler();

}  // namespace lbmshape::temporary_files
