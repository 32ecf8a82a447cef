// The paper's test input: uniform random noise added to the distance field
// (section 5.1, Fig. 4: "random noise (up to 5% of its origin value)").
#pragma once

#include <cstdint>

#include "lbmshape/core/volume.hpp"

namespace lbmshape {

struct FieldNoise {
  // Each cell's value X becomes X + u * amplitude * max|X|, u uniform in
  // [-1, 1]: amplitude 0.05 is "up to 5 %" of the field's magnitude. 0 is off.
  double amplitude = 0.0;
  uint32_t seed = 1;
};

// Deterministic for a seed, whatever the thread count.
void addFieldNoise(Volume& field, const FieldNoise& noise);

}  // namespace lbmshape
