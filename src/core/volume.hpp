// A dense scalar field on a regular grid: the signed distance field X and the
// per-cell parameters of the lattice Boltzmann solver all travel as Volumes.
#pragma once

#include <algorithm>
#include <vector>

#include "lbmshape/core/extent.hpp"

namespace lbmshape {

class Volume {
public:
  Volume() = default;
  explicit Volume(Extent3 extent, float fill = 0.0f) : extent_(extent), values_(extent.cells(), fill) {}

  const Extent3& extent() const { return extent_; }
  size_t size() const { return values_.size(); }

  float& at(int x, int y, int z) { return values_[extent_.index(x, y, z)]; }
  float at(int x, int y, int z) const { return values_[extent_.index(x, y, z)]; }
  float& operator[](size_t i) { return values_[i]; }
  float operator[](size_t i) const { return values_[i]; }

  float* data() { return values_.data(); }
  const float* data() const { return values_.data(); }
  std::vector<float>& values() { return values_; }
  const std::vector<float>& values() const { return values_; }

private:
  Extent3 extent_;
  std::vector<float> values_;
};

}  // namespace lbmshape
