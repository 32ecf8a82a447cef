// lbmshape.set_log_handler: the library's messages (progress, what was
// written, warnings, -v's stage times) to a Python function instead of the
// process's stderr, which a notebook does not show (Jupyter prints a cell's
// sys.stdout and sys.stderr, not file descriptor 2) and a program's logging
// does not see.
#pragma once

#include <pybind11/pybind11.h>

namespace lbmshape::python {

// handler(kind, message): kind "info", "verbose", "warning" or "progress",
// the message without stderr's "lbmshape: " prefix; called on the thread
// that logs it, with the GIL. None sends the messages to stderr again.
void setLogHandler(const pybind11::object& handler);

// At exit, once the calls under way have stopped: the messages go to
// stderr again, for a handler called from another thread while the
// interpreter ends would take the GIL from a finalizing Python.
void releaseLogHandlerAtExit();

}  // namespace lbmshape::python
