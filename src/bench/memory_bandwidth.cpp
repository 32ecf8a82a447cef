#include "bench/memory_bandwidth.hpp"

#include <algorithm>
#include <vector>

#include "core/stopwatch.hpp"
#include "gpu/gpu_buffer.hpp"
#include "gpu/gpu_context.hpp"

namespace lbmshape {
namespace {

constexpr size_t arrayBytes = size_t(256) << 20;  // far beyond any last-level cache
constexpr int repetitions = 5;

// STREAM "scale": b = s a. Read and write traffic, like the lattice step (the
// compiler cannot turn it into a memcpy with non-temporal stores).
BandwidthMeasurement hostBandwidth()
{
  const size_t n = arrayBytes / sizeof(float);
  std::vector<float> a(n), b(n);
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; ++i) a[i] = float(i % 1024), b[i] = 0.0f;  // first touch by the same threads
  double best = 1e30;
  for (int r = 0; r < repetitions; ++r) {
    Stopwatch watch;
    const float s = 1.0f + 1e-3f * float(r);
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; ++i) b[i] = s * a[i];
    best = std::min(best, watch.ms());
  }
  volatile float sink = b[n / 2];
  (void)sink;
  return {2.0 * double(arrayBytes) / (best * 1e-3) / 1e9, "host STREAM scale, " + std::to_string(arrayBytes >> 20) + " MiB arrays, best of 5"};
}

BandwidthMeasurement deviceCopyBandwidth(gpu::GpuContext& context)
{
  using Usage = vk::BufferUsageFlagBits;
  gpu::GpuBuffer from(context, arrayBytes, Usage::eTransferSrc | Usage::eTransferDst, gpu::MemoryUse::Device);
  gpu::GpuBuffer to(context, arrayBytes, Usage::eTransferDst, gpu::MemoryUse::Device);
  context.runAndWait([&](vk::CommandBuffer cmd) { cmd.fillBuffer(from.handle(), 0, VK_WHOLE_SIZE, 0u); });
  double best = 1e30;
  for (int r = 0; r < repetitions; ++r) {
    Stopwatch watch;
    context.runAndWait([&](vk::CommandBuffer cmd) { cmd.copyBuffer(from.handle(), to.handle(), vk::BufferCopy(0, 0, arrayBytes)); });
    best = std::min(best, watch.ms());
  }
  return {2.0 * double(arrayBytes) / (best * 1e-3) / 1e9, "vkCmdCopyBuffer of " + std::to_string(arrayBytes >> 20) + " MiB, best of 5"};
}

}  // namespace

BandwidthMeasurement measureMemoryBandwidth(gpu::GpuContext* context)
{
  if (!context || context->description().type == "cpu") return hostBandwidth();
  return deviceCopyBandwidth(*context);
}

}  // namespace lbmshape
