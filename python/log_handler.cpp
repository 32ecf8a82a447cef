#include "log_handler.hpp"

#include <atomic>
#include <iostream>
#include <memory>
#include <string>

#include "lbmshape/core/log.hpp"

namespace py = pybind11;

namespace lbmshape::python {
namespace {

std::atomic<bool> pythonEnding{false};

const char* kindName(log::Kind kind)
{
  switch (kind) {
  case log::Kind::Verbose: return "verbose";
  case log::Kind::Warning: return "warning";
  case log::Kind::Progress: return "progress";
  case log::Kind::Info: break;
  }
  return "info";
}

// The handler, held by the sink's copies on any thread; the last one drops
// the reference with the GIL, or leaves it once Python is ending.
std::shared_ptr<py::object> held(const py::object& handler)
{
  return std::shared_ptr<py::object>(new py::object(handler), [](py::object* function) {
    if (pythonEnding) {
      function->release();  // the interpreter may be gone: never decremented
      delete function;
      return;
    }
    py::gil_scoped_acquire gil;
    delete function;
  });
}

}  // namespace

void setLogHandler(const py::object& handler)
{
  if (handler.is_none()) {
    log::setSink({});
    return;
  }
  if (!PyCallable_Check(handler.ptr()))
    throw py::type_error("handler must be a function of (kind, message), or None, not " +
                         py::str(py::type::of(handler).attr("__name__")).cast<std::string>());
  if (pythonEnding) return;  // a handler set by another exit handler: stderr stays
  log::setSink([function = held(handler)](log::Kind kind, const std::string& message) {
    if (pythonEnding) {
      std::cerr << (kind == log::Kind::Warning ? "lbmshape: warning: " : "lbmshape: ") << message << '\n';
      return;
    }
    py::gil_scoped_acquire gil;
    // A path's bytes may not be UTF-8 (messages keep them as they are):
    // escaped, where a strict decoding would lose the message.
    const auto text = py::reinterpret_steal<py::object>(
        PyUnicode_DecodeUTF8(message.data(), py::ssize_t(message.size()), "backslashreplace"));
    try {
      if (!text) throw py::error_already_set();
      (*function)(kindName(kind), text);
    } catch (py::error_already_set& e) {
      // As Python reports an exception in a callback it cannot raise
      // (sys.unraisablehook): the call goes on, its message lost.
      e.discard_as_unraisable("lbmshape's log handler");
    }
  });
}

void releaseLogHandlerAtExit()
{
  pythonEnding = true;
  log::setSink({});
}

}  // namespace lbmshape::python
