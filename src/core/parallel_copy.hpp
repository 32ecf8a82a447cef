// Copies large blocks of memory with every thread: a field read back from
// the device (64 MB at 256^3) copied by one thread took longer than the
// device needed to compute it (the morph's frames on an H100's host).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>

namespace lbmshape {

inline void parallelCopy(void* to, const void* from, size_t bytes)
{
  constexpr size_t chunk = size_t(1) << 20;  // below this a thread's start costs more than it saves
  const size_t chunks = (bytes + chunk - 1) / chunk;
#pragma omp parallel for schedule(static) if (chunks > 1)
  for (size_t c = 0; c < chunks; ++c) {
    const size_t first = c * chunk;
    std::memcpy(static_cast<std::byte*>(to) + first, static_cast<const std::byte*>(from) + first,
                std::min(chunk, bytes - first));
  }
}

}  // namespace lbmshape
