// Ctrl-C (SIGINT), SIGTERM (what `kill`, `timeout` and batch schedulers
// send) and SIGHUP (a closed terminal) as a request to stop: the first sets
// a flag that long jobs check between frames, stages and batches of work,
// so they stop within a fraction of a second with only complete files
// written, and the process exits with 128 + the signal's number (130, 143,
// 129), as a shell reports a process the signal killed. A second signal
// ends the process at once, as usual, after removing the temporary files of
// writes under way (temporary_files.hpp).
//
// A program that links the library can ask for the same stop itself
// (requestStop: a Cancel button), and clear it before its next call; a host
// with signal handlers of its own (Python) lends SIGINT to the flag only
// while a call runs (SigintStopsCalls). One call among several (a job of a
// batch that runs on threads of its own) is stopped alone through the
// std::stop_token it was given (CallStop).
#pragma once

#include <functional>
#include <stop_token>
#include <string>
#include <vector>

#include <signal.h>  // struct sigaction

namespace lbmshape::interrupt {

// The command line's handlers, for the life of the process.
void installHandler();
// Whether the process, or the call under way on this thread (CallStop), was
// asked to stop. On a thread the call lends work to, ask a Watch made on the
// call's thread instead.
bool requested();
// The first signal received (SIGINT, SIGTERM or SIGHUP), 0 before any or
// where the program asked (requestStop).
int signalReceived();
// Throws Interrupted with `whatWasDone` if a stop was requested (requested()).
void check(const std::string& whatWasDone);
// The same, asking whatWasDone() only when stopping: what is complete may
// only be known once the work under way has been wound down.
void check(const std::function<std::string()>& whatWasDone);

// Asks every call under way, on any thread, to stop at its next check, as
// the first Ctrl-C does; they throw Interrupted (exit code 130, signal 0).
// The request stands until clearStopRequest: later calls stop at once.
void requestStop();
// Forgets a request (the program's or a signal's), so that the next call
// runs. The command line never clears: a process that was asked to stop
// ends.
void clearStopRequest();

// For the life of this object, a stop requested through `token` stops the
// call on this thread as requestStop would, and that call alone: its checks
// throw Interrupted ("stopped: ...", signal 0). Made at the start of a
// library call given a token; a token that cannot be stopped (a default
// one) changes nothing. Nested calls each add their own.
class CallStop {
public:
  explicit CallStop(std::stop_token token);
  // On a thread that a call lends work to: the call's tokens, as `Watch`
  // took them on the call's thread.
  explicit CallStop(const class Watch& call);
  ~CallStop();
  CallStop(const CallStop&) = delete;
  CallStop& operator=(const CallStop&) = delete;

private:
  size_t added_ = 0;
};

// requested() for the threads of a parallel region (or a std::thread) that
// does a call's work: the call's tokens are its thread's (CallStop), which
// those threads do not see. Made on the call's thread before the region.
class Watch {
public:
  Watch();
  bool requested() const;

private:
  friend class CallStop;
  std::vector<std::stop_token> tokens_;
};

// For a host with its own SIGINT handler (Python's raises KeyboardInterrupt,
// but only once the call returns to it): for the life of this object SIGINT
// sets the stop flag instead, every time (a second Ctrl-C does not end the
// host); the host's handler comes back at the end. A SIGINT the host
// ignores, or leaves to end the process, stays so. Make one on the thread that handles the host's
// signals, around a call that runs without it.
class SigintStopsCalls {
public:
  SigintStopsCalls();
  ~SigintStopsCalls();
  SigintStopsCalls(const SigintStopsCalls&) = delete;
  SigintStopsCalls& operator=(const SigintStopsCalls&) = delete;
  // Whether a SIGINT came while this object was in place.
  bool caughtOne() const;

private:
  struct sigaction host_ = {};
  bool installed_ = false;
};

}  // namespace lbmshape::interrupt
