#include "lbmshape/pipeline/morph_front.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "lbmshape/lbm/frozen_bricks.hpp"

namespace lbmshape {
namespace {

// D after each step: D[0] = 1, D[n + 1] = D[n] r(Cs of step n).
std::vector<double> decayAfterEachStep(const MorphSchedule& schedule)
{
  std::vector<double> D(size_t(schedule.totalSteps()) + 1, 1.0);
  for (int n = 0; n < schedule.totalSteps(); ++n) {
    const double cs = schedule.csAt(n);
    D[size_t(n) + 1] = D[size_t(n)] * (1.0 - cs / 2.0) / (1.0 + cs / 2.0);
  }
  return D;
}

}  // namespace

MorphFront::MorphFront(const BandField& source, const BandField& target, const std::vector<uint8_t>& streams,
                       double reach, const MorphSchedule& schedule, double keepNearTarget)
    : first_(source.bricks().activeCount()), last_(source.bricks().activeCount()),
      awakeFrom_(source.bricks().activeCount()), awakeTo_(source.bricks().activeCount()),
      nearTarget_(source.bricks().activeCount()), totalSteps_(schedule.totalSteps())
{
  const std::vector<double> D = decayAfterEachStep(schedule);
  const std::vector<float>& A = source.values();
  const std::vector<float>& T = target.values();
  const double W = reach;
  if (!(W > 0.0)) throw std::invalid_argument("a morph front's reach must be positive");
#pragma omp parallel for schedule(static)
  for (size_t s = 0; s < first_.size(); ++s) {
    // The hull of the D for which some cell of the brick has |X(D)| < W.
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (size_t i = s * brickCells; i < (s + 1) * brickCells; ++i) {
      if (!streams[i]) continue;
      const double a = A[i], t = T[i], d = a - t;
      double from = 0.0, to = 1.0;  // X(D) = t + d D over D in [0, 1]
      if (d == 0.0) {
        if (std::abs(t) >= W) continue;
      } else {
        from = std::max(from, std::min((-W - t) / d, (W - t) / d));
        to = std::min(to, std::max((-W - t) / d, (W - t) / d));
        if (from > to) continue;
      }
      lo = std::min(lo, from);
      hi = std::max(hi, to);
    }
    // Step n spans D from D[n] down to D[n + 1]: it streams while the two
    // ranges meet, a contiguous run of steps since D falls.
    int first = totalSteps_, last = -1;
    for (int n = 0; n < totalSteps_; ++n)
      if (D[size_t(n) + 1] <= hi && D[size_t(n)] >= lo) {
        first = std::min(first, n);
        last = n;
      }
    first_[s] = first;
    last_[s] = last;
    bool near = false;
    for (size_t i = s * brickCells; i < (s + 1) * brickCells && !near; ++i) near = std::abs(T[i]) <= keepNearTarget;
    nearTarget_[s] = near;
  }
  // A brick must be updated from the step before a brick of its 27 first
  // streams (whose first step pulls the state that step makes) through the
  // last step one streams.
  const std::vector<int32_t> around = source.bricks().neighbourTable();
#pragma omp parallel for schedule(static)
  for (size_t s = 0; s < first_.size(); ++s) {
    int from = totalSteps_, to = -1;
    for (int k = 0; k < 27; ++k) {
      const int32_t n = around[s * 27 + size_t(k)];
      if (n == noBrick || first_[size_t(n)] > last_[size_t(n)]) continue;
      from = std::min(from, first_[size_t(n)] - 1);
      to = std::max(to, last_[size_t(n)]);
    }
    awakeFrom_[s] = from;
    awakeTo_[s] = to;
  }
}

std::vector<uint8_t> MorphFront::heldDuring(int step) const
{
  std::vector<uint8_t> motion(first_.size());
  for (size_t s = 0; s < motion.size(); ++s) {
    BrickMotion m = BrickMotion::Streams;
    if (step < first_[s] || step > last_[s])
      m = !nearTarget_[s] && (step < awakeFrom_[s] || step > awakeTo_[s]) ? BrickMotion::Frozen : BrickMotion::Held;
    motion[s] = uint8_t(m);
  }
  return motion;
}

int MorphFront::sameUntil(int step) const
{
  int next = totalSteps_;
  const auto change = [&](int from, int to) {  // a run [from, to] of steps
    if (from > to) return;
    if (from > step) next = std::min(next, from);
    if (to + 1 > step) next = std::min(next, to + 1);
  };
  for (size_t s = 0; s < first_.size(); ++s) {
    change(first_[s], last_[s]);
    if (!nearTarget_[s]) change(awakeFrom_[s], awakeTo_[s]);
  }
  return std::max(next, step + 1);
}

double MorphFront::meanFrozenFraction() const
{
  if (first_.empty() || totalSteps_ == 0) return 0.0;
  double frozenSteps = 0.0;
  for (size_t s = 0; s < first_.size(); ++s) {
    if (nearTarget_[s]) continue;
    const int from = std::max(awakeFrom_[s], 0), to = std::min(awakeTo_[s], totalSteps_ - 1);
    frozenSteps += totalSteps_ - std::max(0, to - from + 1);
  }
  return frozenSteps / (double(first_.size()) * totalSteps_);
}

double MorphFront::meanStreamingFraction() const
{
  if (first_.empty() || totalSteps_ == 0) return 0.0;
  double streamingSteps = 0.0;
  for (size_t s = 0; s < first_.size(); ++s) streamingSteps += std::max(0, last_[s] - first_[s] + 1);
  return streamingSteps / (double(first_.size()) * totalSteps_);
}

}  // namespace lbmshape
