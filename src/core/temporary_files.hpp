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

// Held while a listed file or folder is being made. The handler below runs
// on one thread while the others go on: without this, a writer could make
// its (already listed) file just after the handler unlinked that name, and
// the process would end with it left behind. Once the handler has begun, a
// new Creation never returns: the process is about to end.
class Creation {
public:
  Creation();
  ~Creation();
  Creation(const Creation&) = delete;
  Creation& operator=(const Creation&) = delete;
};

// Removes every listed file (and every listed folder that is empty), after
// waiting (briefly) for the Creations under way on other threads. The
// process must end right after. Async-signal-safe: for a signal handler, or
// for a process that ends without unwinding (core/last_resort.hpp).
void removeAllFromSignalHandler();

}  // namespace lbmshape::temporary_files
