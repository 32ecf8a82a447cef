#include "lbmshape/bench/memory_bandwidth.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "lbmshape/core/stopwatch.hpp"
#include "lbmshape/gpu/compute_program.hpp"
#include "lbmshape/gpu/gpu_buffer.hpp"
#include "lbmshape/gpu/gpu_context.hpp"

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
  return {2.0 * double(arrayBytes) / (best * 1e-3) / 1e9,
          "host STREAM scale, " + std::to_string(arrayBytes >> 20) + " MiB arrays, best of 5"};
}

struct ScaleParameters {
  uint32_t count;  // vec4s
  float scale;
};

// One submission of `passes` dispatches of bandwidth_scale.comp, from `set`'s
// first buffer to its second; its wall time in ms.
double timeScalePasses(gpu::GpuContext& context, gpu::ComputeProgram& program, vk::DescriptorSet set,
                       const ScaleParameters& push, int passes)
{
  const uint32_t groups = uint32_t(std::min<uint64_t>((uint64_t(push.count) + 255) / 256, 65535));
  Stopwatch watch;
  context.runAndWait([&](vk::CommandBuffer cmd) {
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, set, {});
    cmd.pushConstants<ScaleParameters>(*program.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
    for (int i = 0; i < passes; ++i) {
      if (i > 0) {  // each pass writes what the last wrote
        const vk::MemoryBarrier written(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eShaderWrite);
        cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eComputeShader, {},
                            written, {}, {});
      }
      cmd.dispatch(groups, 1, 1);
    }
  });
  return watch.ms();
}

}  // namespace

BandwidthMeasurement measureDeviceBandwidth(gpu::GpuContext& context, vk::DeviceSize bytes, double warmupMs)
{
  bytes = std::min<vk::DeviceSize>(bytes, context.limits().maxStorageBufferRange) / 16 * 16;
  using Usage = vk::BufferUsageFlagBits;
  using T = vk::DescriptorType;
  gpu::GpuBuffer from(context, bytes, Usage::eStorageBuffer | Usage::eTransferDst, gpu::MemoryUse::Device);
  gpu::GpuBuffer to(context, bytes, Usage::eStorageBuffer, gpu::MemoryUse::Device);
  gpu::ComputeProgram& program = context.program(
      {"bandwidth_scale", {{0, T::eStorageBuffer, 1, {}}, {1, T::eStorageBuffer, 1, {}}}, {}, sizeof(ScaleParameters)});
  const vk::DescriptorPoolSize poolSize(T::eStorageBuffer, 2);
  vk::raii::DescriptorPool pool(
      context.device(),
      vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, poolSize));
  vk::raii::DescriptorSets sets(context.device(), vk::DescriptorSetAllocateInfo(*pool, *program.setLayout));
  const vk::DescriptorBufferInfo a(from.handle(), 0, VK_WHOLE_SIZE), b(to.handle(), 0, VK_WHOLE_SIZE);
  context.device().updateDescriptorSets({vk::WriteDescriptorSet(*sets[0], 0, 0, T::eStorageBuffer, {}, a),
                                         vk::WriteDescriptorSet(*sets[0], 1, 0, T::eStorageBuffer, {}, b)},
                                        {});
  context.runAndWait(
      [&](vk::CommandBuffer cmd) { cmd.fillBuffer(from.handle(), 0, VK_WHOLE_SIZE, 0x3f800000u); });  // 1.0f
  const ScaleParameters push{uint32_t(bytes / 16), 1.001f};

  // A pass over 256 MiB takes 0.2 ms on an H100, no more than a submission's
  // latency: a timed run repeats it for about 50 ms, after the warm-up.
  const double once = timeScalePasses(context, program, *sets[0], push, 1);
  const int passes = std::clamp(int(std::ceil(50.0 / std::max(once, 1e-3))), 1, 1000);
  for (Stopwatch warm; warm.ms() < warmupMs;) timeScalePasses(context, program, *sets[0], push, passes);
  double best = 1e30;
  for (int r = 0; r < repetitions; ++r)
    best = std::min(best, timeScalePasses(context, program, *sets[0], push, passes) / passes);
  return {2.0 * double(bytes) / (best * 1e-3) / 1e9, "compute-shader scale b = s a, " + std::to_string(bytes >> 20) +
                                                         " MiB arrays, best of " + std::to_string(repetitions) +
                                                         " runs of " + std::to_string(passes) + " passes"};
}

BandwidthMeasurement measureMemoryBandwidth(gpu::GpuContext* context)
{
  if (!context || context->description().isCpu()) return hostBandwidth();
  return measureDeviceBandwidth(*context, arrayBytes, 500.0);
}

}  // namespace lbmshape
