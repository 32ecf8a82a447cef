// Ctrl-C (SIGINT), SIGTERM (what `kill`, `timeout` and batch schedulers
// send) and SIGHUP (a closed terminal) as a request to stop: the first sets
// a flag that long jobs check between frames, stages and batches of work,
// so they stop within a fraction of a second with only complete files
// written, and the process exits with 128 + the signal's number (130, 143,
// 129), as a shell reports a process the signal killed. A second signal
// ends the process at once, as usual, after removing the temporary files of
// writes under way (temporary_files.hpp).
#pragma once

#include <functional>
#include <string>

namespace lbmshape::interrupt {

void installHandler();
bool requested();
// The first signal received (SIGINT, SIGTERM or SIGHUP); 0 before any.
int signalReceived();
// Throws Interrupted with `whatWasDone` if a stop was requested.
void check(const std::string& whatWasDone);
// The same, asking whatWasDone() only when stopping: what is complete may
// only be known once the work under way has been wound down.
void check(const std::function<std::string()>& whatWasDone);

}  // namespace lbmshape::interrupt
