#include "lbmshape/core/interrupt.hpp"

#include <atomic>
#include <cstdint>
#include <ctime>
#include <csignal>

#include <signal.h>  // sigaction

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/temporary_files.hpp"

namespace lbmshape::interrupt {
namespace {
constexpr int handled[] = {SIGINT, SIGTERM, SIGHUP};
// What asked to stop first: a signal's number, byTheProgram, or 0 (nothing).
constexpr int byTheProgram = -1;
std::atomic<int> received{0};
std::atomic<int> sigintsWhileHosted{0};  // SIGINTs that SigintStopsCalls took from its host
std::atomic<int64_t> firstAtNs{0};       // CLOCK_MONOTONIC of the first
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

// The handlers have C linkage (sigaction's) and internal linkage (static):
// exported, a host's function of the same name replaced them.
extern "C" {
static void onSignal(int signal)
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

// A host's SIGINT (SigintStopsCalls): a request every time, never the end
// of the host.
static void onHostedSigint(int signal)
{
  ++sigintsWhileHosted;
  int none = 0;
  received.compare_exchange_strong(none, signal);
}
}  // extern "C"

std::string stoppedBy(int signal)
{
  switch (signal) {
  case SIGTERM: return "terminated (SIGTERM): ";
  case SIGHUP: return "hung up (SIGHUP): ";
  case byTheProgram: return "stopped: ";
  default: return "interrupted: ";
  }
}

[[noreturn]] void stop(int signal, const std::string& whatWasDone)
{
  throw Interrupted(stoppedBy(signal) + whatWasDone, signal == byTheProgram ? 0 : signal);
}

// The tokens of the calls under way on this thread (CallStop), innermost
// last.
thread_local std::vector<std::stop_token> callTokens;

// What stops a call with these tokens: a signal's number, byTheProgram, or 0.
int stopOf(const std::vector<std::stop_token>& tokens)
{
  if (const int signal = received) return signal;
  for (const std::stop_token& token : tokens)
    if (token.stop_requested()) return byTheProgram;
  return 0;
}

int stopOfThisThread() { return stopOf(callTokens); }
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

bool requested() { return stopOfThisThread() != 0; }
int signalReceived() { return received == byTheProgram ? 0 : int(received); }

void check(const std::string& whatWasDone)
{
  if (const int signal = stopOfThisThread()) stop(signal, whatWasDone);
}

void check(const std::function<std::string()>& whatWasDone)
{
  if (const int signal = stopOfThisThread()) stop(signal, whatWasDone());
}

CallStop::CallStop(std::stop_token token)
{
  if (!token.stop_possible()) return;
  callTokens.push_back(std::move(token));
  added_ = 1;
}

CallStop::CallStop(const Watch& call)
{
  callTokens.insert(callTokens.end(), call.tokens_.begin(), call.tokens_.end());
  added_ = call.tokens_.size();
}

CallStop::~CallStop() { callTokens.resize(callTokens.size() - added_); }

Watch::Watch() : tokens_(callTokens) {}

bool Watch::requested() const { return stopOf(tokens_) != 0; }

void requestStop()
{
  int none = 0;
  received.compare_exchange_strong(none, byTheProgram);
}

void clearStopRequest()
{
  received = 0;
  firstAtNs = 0;
}

SigintStopsCalls::SigintStopsCalls()
{
  // Counted afresh even where nothing is lent: an earlier lending's count
  // made caughtOne() true for a host that ignores SIGINT.
  sigintsWhileHosted = 0;
  // A host that ignores SIGINT, or leaves it to end the process, keeps
  // its choice.
  if (sigaction(SIGINT, nullptr, &host_) != 0) return;
  if (!(host_.sa_flags & SA_SIGINFO) && (host_.sa_handler == SIG_IGN || host_.sa_handler == SIG_DFL)) return;
  struct sigaction action = {};
  action.sa_handler = onHostedSigint;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  installed_ = sigaction(SIGINT, &action, nullptr) == 0;
}

SigintStopsCalls::~SigintStopsCalls()
{
  if (installed_) sigaction(SIGINT, &host_, nullptr);
}

bool SigintStopsCalls::caughtOne() const { return installed_ && sigintsWhileHosted > 0; }

}  // namespace lbmshape::interrupt
