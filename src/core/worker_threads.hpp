// OpenMP's runtime (libgomp) ends the whole process, with exit code 1 and a
// message of its own, when it cannot create a thread: under a memory limit
// (ulimit -v) or a thread limit, a parallel loop deep inside a job would end
// lbmshape without its error line or its cleanup. A thread that runs
// parallel regions calls this first, while memory is still free: it creates
// its worker threads where a failure can be seen (std::thread throws), lets
// OpenMP use only as many as could be made, and starts OpenMP's own thread
// pool for this thread at once, which OpenMP keeps for every later region.
#pragma once

namespace lbmshape {

// Returns the number of threads this thread's parallel regions will use.
int prepareParallelRegions();

}  // namespace lbmshape
