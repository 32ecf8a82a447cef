// Copies between host memory and device buffers through one host-visible
// staging buffer, a chunk at a time, so that a buffer of any size crosses
// in the staging buffer's room: the narrow band's moments, field and lists,
// which may be larger than any one allocation the host can map.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "lbmshape/core/parallel_copy.hpp"
#include "lbmshape/gpu/gpu_buffer.hpp"
#include "lbmshape/gpu/gpu_context.hpp"

namespace lbmshape::gpu {

class StagedCopies {
public:
  // A staging buffer of `stagingBytes`, host-visible and cached for reading.
  StagedCopies(GpuContext& context, uint64_t stagingBytes);

  // Fills `bytes` of a device buffer through the staging buffer, a chunk of
  // whole `unit`s at a time: fill(first, count, to) writes units
  // [first, first + count) at `to`.
  template <class Fill>
  void uploadUnits(const GpuBuffer& target, uint64_t bytes, uint64_t unit, Fill fill, uint64_t targetOffset = 0)
  {
    const uint64_t unitsPerChunk = std::max<uint64_t>(1, staging_.bytes() / unit), units = (bytes + unit - 1) / unit;
    for (uint64_t first = 0; first < units; first += unitsPerChunk) {
      const uint64_t count = std::min(unitsPerChunk, units - first);
      const uint64_t chunk = std::min(count * unit, bytes - first * unit);
      fill(first, count, staging_.mapped());
      context_.runAndWait([&](vk::CommandBuffer cmd) {
        cmd.copyBuffer(staging_.handle(), target.handle(), vk::BufferCopy(0, targetOffset + first * unit, chunk));
      });
    }
  }

  // Fills `units` pieces of `unitBytes` of a device buffer, piece u at offset
  // u * targetStride, through the staging buffer a chunk at a time:
  // fill(first, count, to) packs pieces [first, first + count) at `to`.
  // `before` is recorded ahead of the first chunk's copy, with its own
  // barrier, and `after` behind the last one's, in the same submissions.
  // Pieces that follow one another (targetStride == unitBytes) go as one
  // region a chunk.
  template <class Fill, class Before, class After>
  void uploadStrided(const GpuBuffer& target, uint64_t units, uint64_t unitBytes, uint64_t targetStride, Fill fill,
                     Before before, After after)
  {
    const uint64_t unitsPerChunk = std::max<uint64_t>(1, staging_.bytes() / unitBytes);
    std::vector<vk::BufferCopy> regions;
    for (uint64_t first = 0; first < units; first += unitsPerChunk) {
      const uint64_t count = std::min(unitsPerChunk, units - first);
      fill(first, count, staging_.mapped());
      regions.clear();
      if (targetStride == unitBytes)
        regions.emplace_back(0, first * unitBytes, count * unitBytes);
      else
        for (uint64_t k = 0; k < count; ++k) regions.emplace_back(k * unitBytes, (first + k) * targetStride, unitBytes);
      context_.runAndWait([&](vk::CommandBuffer cmd) {
        if (first == 0) before(cmd);
        cmd.copyBuffer(staging_.handle(), target.handle(), regions);
        if (first + count >= units) after(cmd);
      });
    }
  }

  // Copies `bytes` from host memory into a device buffer, from `targetOffset` on.
  void upload(const void* data, uint64_t bytes, const GpuBuffer& target, uint64_t targetOffset = 0);

  // Copies `units` pieces of `unitBytes` of a device buffer, piece u at
  // offset u * sourceStride, packed into host memory, through the staging
  // buffer a chunk at a time, after what the command buffer `before`
  // records (a barrier to transfer reads included). With `wholeStrides`
  // the staging takes every stride whole, one region a chunk, and the host
  // keeps each piece (where the copies cross a bus: BandVulkanSolver::startFrom() says why).
  template <class Before>
  void downloadUnits(const GpuBuffer& source, uint64_t units, uint64_t unitBytes, uint64_t sourceStride, void* data,
                     Before before, bool wholeStrides = false)
  {
    if (source.mapped() && sourceStride == unitBytes) {  // readable where it lies: no staging copy
      context_.runAndWait([&](vk::CommandBuffer cmd) {
        before(cmd);
        cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eTransfer,
                            vk::PipelineStageFlagBits::eHost, {},
                            vk::MemoryBarrier(vk::AccessFlagBits::eShaderWrite | vk::AccessFlagBits::eTransferWrite,
                                              vk::AccessFlagBits::eHostRead),
                            {}, {});
      });
      parallelCopy(static_cast<std::byte*>(data), source.mapped(), units * unitBytes);
      return;
    }
    wholeStrides = wholeStrides && sourceStride != unitBytes;
    const uint64_t stagedBytes = wholeStrides ? sourceStride : unitBytes;
    const uint64_t unitsPerChunk = std::max<uint64_t>(1, staging_.bytes() / stagedBytes);
    std::vector<vk::BufferCopy> regions;
    for (uint64_t first = 0; first < units; first += unitsPerChunk) {
      const uint64_t count = std::min(unitsPerChunk, units - first);
      regions.clear();
      if (sourceStride == unitBytes || wholeStrides)  // contiguous: one copy
        regions.emplace_back(first * stagedBytes, 0, count * stagedBytes);
      else
        for (uint64_t k = 0; k < count; ++k) regions.emplace_back((first + k) * sourceStride, k * unitBytes, unitBytes);
      context_.runAndWait([&](vk::CommandBuffer cmd) {
        if (first == 0) before(cmd);
        cmd.copyBuffer(source.handle(), staging_.handle(), regions);
        cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eHost, {},
                            vk::MemoryBarrier(vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eHostRead), {},
                            {});
      });
      std::byte* to = static_cast<std::byte*>(data) + first * unitBytes;
      if (!wholeStrides) {
        parallelCopy(to, staging_.mapped(), count * unitBytes);
        continue;
      }
#pragma omp parallel for schedule(static)
      for (uint64_t k = 0; k < count; ++k)
        std::memcpy(to + k * unitBytes, staging_.mapped() + k * sourceStride, unitBytes);
    }
  }

  // Copies `bytes` of a device buffer into host memory (downloadUnits).
  template <class Before>
  void download(const GpuBuffer& source, uint64_t bytes, void* data, Before before)
  {
    downloadUnits(source, bytes, 1, 1, data, before);
  }

private:
  GpuContext& context_;
  GpuBuffer staging_;
};

}  // namespace lbmshape::gpu
