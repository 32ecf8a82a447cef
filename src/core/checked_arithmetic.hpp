// Sizes computed from untrusted numbers (file headers, glTF accessors) must
// not wrap around: these say whether they would.
#pragma once

#include <cstdint>
#include <optional>

namespace lbmshape {

inline std::optional<uint64_t> checkedAdd(uint64_t a, uint64_t b)
{
  uint64_t sum;
  if (__builtin_add_overflow(a, b, &sum)) return std::nullopt;
  return sum;
}

inline std::optional<uint64_t> checkedMultiply(uint64_t a, uint64_t b)
{
  uint64_t product;
  if (__builtin_mul_overflow(a, b, &product)) return std::nullopt;
  return product;
}

}  // namespace lbmshape
