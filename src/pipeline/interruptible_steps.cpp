#include "lbmshape/pipeline/interruptible_steps.hpp"

#include <algorithm>
#include <cmath>

#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/stopwatch.hpp"

namespace lbmshape {

InterruptibleSteps::InterruptibleSteps(SteppingSolver& solver, std::optional<int> fixedBatch, double batchMs)
    : solver_(solver), fixedBatch_(fixedBatch), batchMs_(batchMs)
{}

int InterruptibleSteps::nextBatch(int remaining) const
{
  if (fixedBatch_) return std::clamp(*fixedBatch_, 1, remaining);
  if (msPerStep_ <= 0.0) return 1;  // the first batch measures the speed
  // At most four times the last batch: one fast measurement (a first step
  // that costs nothing, a cached pipeline) must not commit to hours of steps.
  const double byTime = std::floor(batchMs_ / msPerStep_);
  return int(std::clamp(std::min(byTime, 4.0 * lastBatch_), 1.0, double(remaining)));
}

void InterruptibleSteps::advanceTo(int totalSteps, const std::function<std::string()>& whatWasDone, Progress* progress)
{
  while (solver_.stepsTaken() < totalSteps) {
    interrupt::check(whatWasDone);
    const int batch = nextBatch(totalSteps - solver_.stepsTaken());
    Stopwatch clock;
    solver_.step(batch);
    msPerStep_ = clock.ms() / batch;
    lastBatch_ = batch;
    if (progress) progress->advance(batch);
  }
}

}  // namespace lbmshape
