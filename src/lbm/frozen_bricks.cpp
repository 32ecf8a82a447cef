#include "lbmshape/lbm/frozen_bricks.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

namespace lbmshape {

void FrozenBricks::start()
{
  std::fill(since_.begin(), since_.end(), -1);
  frozenCount_ = 0;
  keepRho_.clear();
  keepFlux_.clear();
}

bool FrozenBricks::freezingNext() const
{
  for (size_t s = 0; s < motion_.size(); ++s)
    if (motion_[s] == uint8_t(BrickMotion::Frozen) && since_[s] < 0) return true;
  return false;
}

std::vector<int32_t> FrozenBricks::beforeSteps(int count, const StepParameters& p, int stepsTaken, int current)
{
  std::vector<int32_t> freezing;
  if (count <= 0) return freezing;
  for (size_t s = 0; s < motion_.size(); ++s)
    if (motion_[s] == uint8_t(BrickMotion::Frozen) && since_[s] < 0) freezing.push_back(int32_t(s));
  if (frozenCount_ + freezing.size() > 0) {
    if (p.perCellOmega || p.paperRule)
      throw std::logic_error("frozen bricks need one omega for every cell: no gamma per cell, no paper rule");
    if (p.source && p.scale != p.decay)
      throw std::logic_error("frozen bricks need a source whose scale is its decay (X_target its fixed point)");
  }
  for (int32_t s : freezing) {
    since_[size_t(s)] = stepsTaken;
    copy_[size_t(s)] = uint8_t(current);
  }
  frozenCount_ += freezing.size();
  // r(c) and 1 - omega of each step to come, by the state it makes.
  const size_t last = size_t(stepsTaken + count);
  keepRho_.resize(last + 1, 1.0);
  keepFlux_.resize(last + 1, 1.0);
  const double c = p.source ? double(p.decay) : 0.0;
  for (size_t n = size_t(stepsTaken) + 1; n <= last; ++n) {
    keepRho_[n] = (1.0 - c / 2.0) / (1.0 + c / 2.0);
    keepFlux_[n] = 1.0 - double(p.omega);
  }
  return freezing;
}

std::vector<FrozenBricks::CatchUp> FrozenBricks::setMotion(const std::vector<uint8_t>& motion, int stepsTaken)
{
  motion_ = motion;
  std::map<std::pair<int, int>, CatchUp> groups;
  for (size_t s = 0; s < since_.size(); ++s) {
    if (since_[s] < 0 || (!motion_.empty() && motion_[s] == uint8_t(BrickMotion::Frozen))) continue;
    if (stepsTaken > since_[s]) {
      CatchUp& group = groups[{since_[s], copy_[s]}];
      group.since = since_[s];
      group.copy = copy_[s];
      group.slots.push_back(int32_t(s));
    }
    since_[s] = -1;
    --frozenCount_;
  }
  std::vector<CatchUp> out;
  for (auto& [key, group] : groups) {
    double R = 1.0, K = 1.0;
    for (int n = group.since + 1; n <= stepsTaken; ++n) R *= keepRho_[size_t(n)], K *= keepFlux_[size_t(n)];
    group.decay = float(2.0 * (1.0 - R) / (1.0 + R));
    group.omega = float(1.0 - K);
    out.push_back(std::move(group));
  }
  return out;
}

}  // namespace lbmshape
