#include "core/interrupt.hpp"

#include <atomic>
#include <csignal>

#include <signal.h>  // sigaction

#include "core/error.hpp"
#include "core/temporary_files.hpp"

namespace lbmshape::interrupt {
namespace {
constexpr int handled[] = {SIGINT, SIGTERM, SIGHUP};
std::atomic<int> received{0};

extern "C" void onSignal(int signal)
{
  int none = 0;
  if (received.compare_exchange_strong(none, signal)) return;  // the first: a request, checked between batches of work
  // A second ends the process at once, as usual, but first removes the
  // temporary files that unwinding would have removed.
  temporary_files::removeAllFromSignalHandler();
  std::signal(signal, SIG_DFL);
  std::raise(signal);  // delivered when this handler returns: the process dies of it, as the shell expects
}

std::string stoppedBy(int signal)
{
  switch (signal) {
  case SIGTERM: return "terminated (SIGTERM): ";
  case SIGHUP: return "hung up (SIGHUP): ";
  default: return "interrupted: ";
  }
}
}  // namespace

void installHandler()
{
  struct sigaction action = {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // system calls go on after the first signal; the flag is checked between batches
  for (int signal : handled) {
    // A signal the parent ignores stays ignored: `nohup lbmshape ...` asks
    // for a job that outlives its terminal.
    struct sigaction current = {};
    if (sigaction(signal, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
    sigaction(signal, &action, nullptr);
  }
}

bool requested() { return received != 0; }
int signalReceived() { return received; }

void check(const std::string& whatWasDone)
{
  if (const int signal = received) throw Interrupted(stoppedBy(signal) + whatWasDone, signal);
}

void check(const std::function<std::string()>& whatWasDone)
{
  if (const int signal = received) throw Interrupted(stoppedBy(signal) + whatWasDone(), signal);
}

}  // namespace lbmshape::interrupt
