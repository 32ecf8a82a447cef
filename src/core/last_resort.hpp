// What the process does when an exception escapes where none can be caught:
// a worker thread of an OpenMP region or of std::thread, where the runtime
// calls std::terminate. Without this, std::bad_alloc in a parallel loop ends
// the process with SIGABRT and a C++ runtime message; with it, every such
// end is one "lbmshape: error:" line and the exit code of the error's kind
// (out of memory: 5), after the temporary files and folders of work under
// way are removed, as after a second Ctrl-C.
//
// The same for a library that aborts the process: Mesa's LLVM aborts
// ("LLVM ERROR: Unable to allocate section memory!") when compiling a shader
// finds no memory, which under a tight `ulimit -v` can happen in the middle
// of a job. SIGABRT then removes the job's temporary files and new empty
// folders and ends with one line and exit 5 (no core dump: the library's
// own message, printed before, names the failure). Builds with AddressSanitizer
// keep the default, so that a sanitizer's abort is never mistaken for one.
#pragma once

namespace lbmshape {

void installLastResortHandler();

}  // namespace lbmshape
