// Which samples of a field are inside (value > isovalue), one bit each, in
// rows of 64-bit words along x. Marching cubes finds cut edges and cubes that
// need triangles with a few word operations per 64 samples, so its time goes
// with the surface, not the grid. A thirty-second of the field's memory.
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

#include "lbmshape/core/volume.hpp"

namespace lbmshape {

class InsideMask {
public:
  // Throws NumericalError when the field holds a NaN or an infinity.
  InsideMask(const Volume& field, float isovalue);

  int words() const { return words_; }
  const uint64_t* row(int y, int z) const { return bits_.data() + (size_t(z) * ny_ + y) * words_; }

  // Word w of the row moved down by one sample: bit b holds sample 64 w + b + 1.
  uint64_t next(const uint64_t* row, int w) const { return (row[w] >> 1) | (w + 1 < words_ ? row[w + 1] << 63 : 0); }

  // Bits of word w for the samples x < count.
  static uint64_t below(int w, int count)
  {
    const int n = count - 64 * w;
    return n >= 64 ? ~uint64_t(0) : n <= 0 ? 0 : (uint64_t(1) << n) - 1;
  }

  // Calls f(x) for each set bit of word w, in increasing x.
  template <class F>
  static void forEachBit(uint64_t bits, int w, F&& f)
  {
    for (; bits; bits &= bits - 1) f(64 * w + std::countr_zero(bits));
  }

private:
  int words_ = 0, ny_ = 0;
  std::vector<uint64_t> bits_;
};

}  // namespace lbmshape
