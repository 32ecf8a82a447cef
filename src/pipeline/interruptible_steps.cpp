#include "pipeline/interruptible_steps.hpp"

#include <algorithm>
#include <cmath>

#include "core/interrupt.hpp"
#include "core/stopwatch.hpp"

namespace lbmshape {

InterruptibleSteps::InterruptibleSteps(LatticeSolver& solver, std::optional<int> fixedBatch, double batchMs)
    : solver_(solver), fixedBatch_(fixedBatch), batchMs_(batchMs)
{
}

int InterruptibleSteps::nextBatch(int remaining) const
{
  if (fixedBatch_) return std::clamp(*fixedBatch_, 1, remaining);
  if (msPerStep_ <= 0.0) return 1;  // the first batch measures the speed
  return int(std::clamp(std::floor(batchMs_ / msPerStep_), 1.0, double(remaining)));
}

void InterruptibleSteps::advanceTo(int totalSteps, const std::function<std::string()>& whatWasDone, Progress* progress)
{
  while (solver_.stepsTaken() < totalSteps) {
    interrupt::check(whatWasDone());
    const int batch = nextBatch(totalSteps - solver_.stepsTaken());
    Stopwatch clock;
    solver_.step(batch);
    msPerStep_ = clock.ms() / batch;
    if (progress) progress->advance(batch);
  }
}

}  // namespace lbmshape
