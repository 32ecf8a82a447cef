#include "lbmshape/pipeline/field_noise.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"

namespace lbmshape {

void addFieldNoise(Volume& field, const FieldNoise& noise)
{
  if (!(noise.amplitude >= 0.0) || !std::isfinite(noise.amplitude))
    throw UsageError(nameOf(Parameter::Noise) + " must be zero or a positive fraction of the field's magnitude");
  if (noise.amplitude == 0.0) return;
  float largest = 0.0f;
  for (size_t i = 0; i < field.size(); ++i) largest = std::max(largest, std::abs(field[i]));
  const float scale = float(noise.amplitude) * largest;
  // One generator per z slice, seeded from (seed, slice): the same noise for
  // any number of threads.
  const Extent3& e = field.extent();
  const size_t slice = size_t(e.nx) * e.ny;
#pragma omp parallel for schedule(static)
  for (int z = 0; z < e.nz; ++z) {
    std::seed_seq seeds{noise.seed, uint32_t(z)};
    std::mt19937 rng(seeds);
    // u in [-1, 1) from the top 24 bits: the same numbers with any standard
    // library, unlike std::uniform_real_distribution.
    for (size_t i = 0; i < slice; ++i) {
      const float u = float(rng() >> 8) * (2.0f / 16777216.0f) - 1.0f;
      field[size_t(z) * slice + i] += scale * u;
    }
  }
}

}  // namespace lbmshape
