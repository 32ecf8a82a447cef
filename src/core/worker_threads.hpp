// OpenMP's runtime (libgomp) ends the whole process, with exit code 1 and a
// message of its own, when it cannot create a thread: under a memory limit
// (ulimit -v) or a thread limit, a parallel loop deep inside a job would end
// lbmshape without its error line or its cleanup. A thread that runs
// parallel regions calls this first, while memory is still free: it creates
// its worker threads where a failure can be seen (std::thread throws), lets
// OpenMP use only as many as could be made, and starts OpenMP's own thread
// pool for this thread at once, which OpenMP keeps for every later region.
#pragma once

#include <functional>

namespace lbmshape {

// Returns the number of threads this thread's parallel regions will use.
int prepareParallelRegions();

// Runs `here` on this thread and `there` on another at the same time, the
// parallel regions of each on half the threads (one each on two cores):
// two jobs of about the same size that parallelise less than perfectly
// (memory-bound loops, serial parts) end sooner side by side than one after
// the other with every thread each (a morph's two distance fields at 128^3:
// 824 -> 658 ms on two cores).
// Under an address-space limit (`ulimit -v`), or where no thread can be
// started, runs them one after the other as they are. An exception from
// either reaches the caller once both have ended.
void runSideBySide(const std::function<void()>& here, const std::function<void()>& there);

}  // namespace lbmshape
