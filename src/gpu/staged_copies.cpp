#include "lbmshape/gpu/staged_copies.hpp"

namespace lbmshape::gpu {

StagedCopies::StagedCopies(GpuContext& context, uint64_t stagingBytes)
    : context_(context),
      staging_(context, stagingBytes, vk::BufferUsageFlagBits::eTransferSrc | vk::BufferUsageFlagBits::eTransferDst,
               MemoryUse::Readback)
{}

void StagedCopies::upload(const void* data, uint64_t bytes, const GpuBuffer& target, uint64_t targetOffset)
{
  uploadUnits(
      target, bytes, 1,
      [&](uint64_t first, uint64_t count, std::byte* to) {
        std::memcpy(to, static_cast<const std::byte*>(data) + first, count);
      },
      targetOffset);
}

}  // namespace lbmshape::gpu
