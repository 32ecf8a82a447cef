#include "lbmshape/core/last_resort.hpp"

#include <atomic>
#include <cstring>
#include <exception>
#include <new>

#include <signal.h>
#include <unistd.h>

#include "lbmshape/core/address_sanitizer.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/temporary_files.hpp"

namespace lbmshape {
namespace {

// Writes one line of printable text without allocating: memory may be
// exactly what ran out.
void writeLine(const char* message)
{
  char line[1024] = "lbmshape: error: ";
  size_t n = std::strlen(line);
  for (const char* c = message; *c && n + 1 < sizeof line; ++c)
    line[n++] = static_cast<unsigned char>(*c) >= 0x20 && static_cast<unsigned char>(*c) < 0x7f ? *c : '?';
  line[n++] = '\n';
  [[maybe_unused]] auto written = ::write(STDERR_FILENO, line, n);
}

// The first thread to end the process does; any other that gets here
// meanwhile (several threads of one parallel loop can run out of memory at
// once) waits for it, so the process still prints one line.
[[noreturn]] void waitForTheFirstToEnd()
{
  for (;;) ::pause();
}
std::atomic_flag ending = ATOMIC_FLAG_INIT;

[[noreturn]] void onTerminate()
{
  if (ending.test_and_set()) waitForTheFirstToEnd();
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
    } catch (...) {}
  }
  temporary_files::removeAllFromSignalHandler();
  writeLine(message);
  ::_exit(code);
}

[[maybe_unused]] void onAbort(int)  // not installed in ASan builds
{
  if (ending.test_and_set()) waitForTheFirstToEnd();
  temporary_files::removeAllFromSignalHandler();
  writeLine(
      "aborted by a library's fatal error (Mesa's shader compiler aborts so when memory runs out); the message before "
      "this line says which");
  ::_exit(int(ExitCode::Device));
}

}  // namespace

void installLastResortHandler()
{
  std::set_terminate(onTerminate);
  if constexpr (!builtWithAddressSanitizer) {
    struct sigaction action = {};
    action.sa_handler = onAbort;
    sigemptyset(&action.sa_mask);
    sigaction(SIGABRT, &action, nullptr);
  }
}

}  // namespace lbmshape
