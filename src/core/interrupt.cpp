#include "core/interrupt.hpp"

#include <atomic>
#include <csignal>

#include <signal.h>  // sigaction

#include "core/error.hpp"
#include "core/temporary_files.hpp"

namespace lbmshape::interrupt {
namespace {
std::atomic<bool> flag{false};

extern "C" void onInterrupt(int)
{
  if (!flag.exchange(true)) return;  // the first Ctrl-C: a request, checked between batches of work
  // The second ends the process at once, as usual, but first removes the
  // temporary files that unwinding would have removed.
  temporary_files::removeAllFromSignalHandler();
  std::signal(SIGINT, SIG_DFL);
  std::raise(SIGINT);  // delivered when this handler returns: the process dies of SIGINT, as the shell expects
}
}  // namespace

void installHandler()
{
  struct sigaction action = {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // system calls go on after the first Ctrl-C; the flag is checked between batches
  sigaction(SIGINT, &action, nullptr);
}
bool requested() { return flag; }

void check(const std::string& whatWasDone)
{
  if (flag) throw Interrupted("interrupted: " + whatWasDone);
}

}  // namespace lbmshape::interrupt
