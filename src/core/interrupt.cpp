#include "core/interrupt.hpp"

#include <atomic>
#include <cstdint>
#include <ctime>
#include <csignal>

#include <signal.h>  // sigaction

#include "core/error.hpp"
#include "core/temporary_files.hpp"

namespace lbmshape::interrupt {
namespace {
constexpr int handled[] = {SIGINT, SIGTERM, SIGHUP};
std::atomic<int> received{0};
std::atomic<int64_t> firstAtNs{0};  // CLOCK_MONOTONIC of the first
// A copy of the first signal this soon after it is the same request, not a
// second one: coreutils' `timeout -s INT` sends its signal to the process
// and then to its process group, which the process is in. A person's second
// Ctrl-C comes later than this.
constexpr int64_t sameRequestNs = 200'000'000;
static_assert(std::atomic<int64_t>::is_always_lock_free, "read and written in a signal handler");

int64_t monotonicNs()
{
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  return int64_t(now.tv_sec) * 1'000'000'000 + now.tv_nsec;
}

extern "C" void onSignal(int signal)
{
  int none = 0;
  if (received.compare_exchange_strong(none, signal)) {  // the first: a request, checked between batches of work
    firstAtNs = monotonicNs();
    return;
  }
  if (signal == received && monotonicNs() - firstAtNs < sameRequestNs) return;
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
