#include "core/last_resort.hpp"

#include <cstring>
#include <exception>
#include <new>

#include <unistd.h>

#include "core/error.hpp"
#include "core/temporary_files.hpp"

namespace lbmshape {
namespace {

// Writes without allocating: memory may be exactly what ran out.
void writeLine(const char* message)
{
  const char* prefix = "lbmshape: error: ";
  [[maybe_unused]] auto a = ::write(STDERR_FILENO, prefix, std::strlen(prefix));
  [[maybe_unused]] auto b = ::write(STDERR_FILENO, message, std::strlen(message));
  [[maybe_unused]] auto c = ::write(STDERR_FILENO, "\n", 1);
}

[[noreturn]] void onTerminate()
{
  int code = int(ExitCode::Device);
  const char* message = "internal error: an exception escaped a worker thread";
  if (const std::exception_ptr escaped = std::current_exception()) {
    try {
      std::rethrow_exception(escaped);
    } catch (const std::bad_alloc&) {
      message = "out of memory";
    } catch (const Error& e) {
      code = int(e.code());
      message = e.what();
    } catch (const std::exception& e) {
      message = e.what();
    } catch (...) {
    }
  }
  temporary_files::removeAllFromSignalHandler();
  writeLine(message);
  ::_exit(code);
}

}  // namespace

void installLastResortHandler() { std::set_terminate(onTerminate); }

}  // namespace lbmshape
