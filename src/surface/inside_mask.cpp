#include "lbmshape/surface/inside_mask.hpp"

#include <cmath>
#include <sstream>

#include "lbmshape/core/error.hpp"

namespace lbmshape {

InsideMask::InsideMask(const Volume& field, float isovalue)
{
  const Extent3 e = field.extent();
  words_ = (e.nx + 63) / 64;
  ny_ = e.ny;
  bits_.assign(size_t(words_) * e.ny * e.nz, 0);
  std::vector<uint64_t> nonFinite(size_t(e.nz), 0);
#pragma omp parallel for schedule(static)
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y) {
      const float* v = field.data() + e.index(0, y, z);
      uint64_t* out = bits_.data() + (size_t(z) * e.ny + y) * words_;
      uint64_t bad = 0;
      for (int x = 0; x < e.nx; ++x) {
        out[x >> 6] |= uint64_t(v[x] > isovalue) << (x & 63);
        bad += !std::isfinite(v[x]);
      }
      nonFinite[z] += bad;
    }
  uint64_t total = 0;
  for (uint64_t n : nonFinite) total += n;
  if (total == 0) return;
  for (size_t i = 0; i < field.size(); ++i)
    if (!std::isfinite(field[i])) {
      const auto [x, y, z] = e.cellAt(i);
      std::ostringstream message;
      message << "the field has " << total << " non-finite values (the first at cell " << x << ", " << y << ", " << z
              << "), so it has no surface to extract";
      throw NumericalError(message.str());
    }
}

}  // namespace lbmshape
