#include "lbmshape/core/worker_threads.hpp"

#include <algorithm>
#include <future>
#include <system_error>
#include <thread>
#include <vector>

#include <omp.h>

#include "lbmshape/core/host_memory.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/log.hpp"

namespace lbmshape {

int prepareParallelRegions()
{
  const int wanted = omp_get_max_threads();
  int made = 0;
  {
    std::vector<std::thread> probes;
    try {
      for (int i = 1; i < wanted; ++i, ++made) probes.emplace_back([] {});
    } catch (const std::system_error&) {}
    for (auto& t : probes) t.join();
  }
  if (made + 1 < wanted) {
    omp_set_num_threads(made + 1);
    log::verbose("only " + std::to_string(made + 1) + " of " + std::to_string(wanted) +
                 " threads could be started; parallel work uses " + std::to_string(made + 1));
  }
  int started = 1;
#pragma omp parallel
  {
#pragma omp single
    started = omp_get_num_threads();
  }
  return started;
}

namespace {

// This thread's parallel regions on `threads` threads until the end of the
// scope.
class RegionThreads {
public:
  explicit RegionThreads(int threads) : before_(omp_get_max_threads()) { omp_set_num_threads(threads); }
  ~RegionThreads() { omp_set_num_threads(before_); }
  RegionThreads(const RegionThreads&) = delete;
  RegionThreads& operator=(const RegionThreads&) = delete;

private:
  int before_;
};

}  // namespace

void runSideBySide(const std::function<void()>& here, const std::function<void()>& there)
{
  // Under an address-space limit, one after the other: a thread of its own
  // costs `there` a malloc arena, 64 MB of address space reserved, and
  // what is left then runs out inside lavapipe, which does not check every
  // allocation (a morph under `ulimit -v 800000` died of SIGSEGV in its
  // shader threads one run in five, against none one after the other).
  if (!addressSpaceUnlimited()) {
    here();
    there();
    return;
  }
  // The threads shared out, half each: one each on two cores, as
  // measured there; on the H100's 16 cores one each made a morph's two
  // signs at 256 take 0.6-1.1 s, single-threaded, beside 14 idle cores.
  const int threads = omp_get_max_threads();
  const int thereThreads = std::max(1, threads / 2), hereThreads = std::max(1, threads - thereThreads);
  std::future<void> other;
  const interrupt::Watch callsStop;  // for `there`'s thread, which is not the call's
  try {
    other = std::async(std::launch::async, [&] {
      const interrupt::CallStop carried(callsStop);
      const RegionThreads share(thereThreads);
      prepareParallelRegions();  // this new thread's pool, where a failure can be seen
      there();
    });
  } catch (const std::system_error&) {
    here();
    there();
    return;
  }
  {
    const RegionThreads share(hereThreads);
    try {
      here();
    } catch (...) {
      other.wait();  // `there` uses what the caller lends both
      throw;
    }
  }
  other.get();
}

}  // namespace lbmshape
