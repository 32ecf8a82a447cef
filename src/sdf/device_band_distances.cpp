#include "lbmshape/sdf/device_band_distances.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

#include "lbmshape/shaders/band_distance_interface.h"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/gpu/gpu_buffer.hpp"
#include "lbmshape/gpu/gpu_context.hpp"
#include "lbmshape/sdf/cell_space.hpp"
#include "lbmshape/sdf/point_triangle.hpp"

namespace lbmshape {
namespace {

namespace shader = band_distance_shader;
using Usage = vk::BufferUsageFlagBits;

constexpr uint64_t kTriangleBytes = 4 * 4 * sizeof(float);  // four vec4: a, b, c, unit normal
// Bricks a submission: 2 M cells, a few ms on a GPU; between submissions
// the host checks for Ctrl-C.
constexpr int kSlotsPerChunk = 4096;
static_assert(kSlotsPerChunk * brickCells / BAND_DISTANCE_WORKGROUP_SIZE <= 65535, "one dispatch a chunk");
static_assert(BAND_DISTANCE_STACK == TriangleBvh::kMaxDepth + 2, "the shader's stack holds any walk of the tree");

// A bound of a box in grid coordinates as a float that still holds it:
// rounded outwards, so no triangle's float corner lies outside its node.
float lower(double v) { return std::nextafter(float(v), -std::numeric_limits<float>::infinity()); }
float upper(double v) { return std::nextafter(float(v), std::numeric_limits<float>::infinity()); }

std::vector<shader::Node> packNodes(const TriangleBvh& bvh, const GridFrame& frame)
{
  std::vector<shader::Node> packed(bvh.nodes().size());
  for (size_t i = 0; i < packed.size(); ++i) {
    const TriangleBvh::Node& n = bvh.nodes()[i];
    const glm::dvec3 lo = frame.toGrid(n.lo), hi = frame.toGrid(n.hi);
    packed[i] = {{lower(lo.x), lower(lo.y), lower(lo.z)}, n.first, {upper(hi.x), upper(hi.y), upper(hi.z)}, n.count};
  }
  return packed;
}

std::vector<glm::vec4> packTriangles(const TriangleBvh& bvh, const GridFrame& frame)
{
  const size_t count = bvh.triangleCount();
  std::vector<glm::vec4> packed(4 * count);
#pragma omp parallel for schedule(static)
  for (size_t slot = 0; slot < count; ++slot) {
    glm::dvec3 a, b, c;
    bvh.slotCorners(uint32_t(slot), a, b, c);
    a = frame.toGrid(a), b = frame.toGrid(b), c = frame.toGrid(c);
    const bool sliver = PreparedTriangle(a, b, c).isSliver();
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    const double normal2 = glm::dot(normal, normal);
    packed[4 * slot] = glm::vec4(glm::vec3(a), sliver ? 1.0f : 0.0f);
    packed[4 * slot + 1] = glm::vec4(glm::vec3(b), 0.0f);
    packed[4 * slot + 2] = glm::vec4(glm::vec3(c), 0.0f);
    packed[4 * slot + 3] = glm::vec4(sliver ? glm::vec3(0.0f) : glm::vec3(normal / std::sqrt(normal2)), 0.0f);
  }
  return packed;
}

// A device-local buffer and the host-visible copy of its contents that the
// first submission copies into it: the uploads go out with the first chunk's
// work, not with a wait each. The host's array goes once it is staged, the
// staging buffer once the first submission has run (release()), so the
// tree is held twice only until then.
struct StagedUpload {
  std::optional<gpu::GpuBuffer> staging;
  gpu::GpuBuffer target;
  template <class T>
  StagedUpload(gpu::GpuContext& context, std::vector<T> data)
      : staging(std::in_place, context, data.size() * sizeof(T), Usage::eTransferSrc, gpu::MemoryUse::Upload),
        target(context, data.size() * sizeof(T), Usage::eStorageBuffer | Usage::eTransferDst, gpu::MemoryUse::Device)
  {
    std::memcpy(staging->mapped(), data.data(), data.size() * sizeof(T));
  }
  void record(vk::CommandBuffer cmd) const
  {
    cmd.copyBuffer(staging->handle(), target.handle(), vk::BufferCopy(0, 0, target.bytes()));
  }
  void release() { staging.reset(); }
};

gpu::ComputeProgram& distanceProgram(gpu::GpuContext& context)
{
  using T = vk::DescriptorType;
  return context.program({"band_distance",
                          {{BAND_DISTANCE_BINDING_NODES, T::eStorageBuffer, 1, {}},
                           {BAND_DISTANCE_BINDING_TRIANGLES, T::eStorageBuffer, 1, {}},
                           {BAND_DISTANCE_BINDING_ORIGINS, T::eStorageBuffer, 1, {}},
                           {BAND_DISTANCE_BINDING_DISTANCES, T::eStorageBuffer, 1, {}}},
                          {},
                          sizeof(shader::Parameters)});
}

}  // namespace

void prepareDeviceBandDistances(gpu::GpuContext& context) { distanceProgram(context); }

bool deviceHoldsTree(uint64_t range, const TriangleBvh& bvh)
{
  return bvh.nodes().size() * sizeof(shader::Node) <= range && bvh.triangleCount() * kTriangleBytes <= range;
}

std::vector<float> deviceBandDistances(gpu::GpuContext& context, const TriangleBvh& bvh, const GridFrame& frame,
                                       const BandCells& cells, double maxVoxels)
{
  constexpr float infinity = std::numeric_limits<float>::infinity();
  std::vector<float> distance(cells.count(), infinity);
  const BrickSet& bricks = cells.bricks();
  const int slots = int(bricks.activeCount());
  if (slots == 0 || bvh.nodes().empty()) return distance;
  if (!deviceHoldsTree(context.limits().maxStorageBufferRange, bvh))
    throw DeviceError("the mesh's " + std::to_string(bvh.triangleCount()) + " triangles do not fit one buffer of " +
                      context.description().name + " for the distances on the device; use --sdf cpu");

  StagedUpload nodes(context, packNodes(bvh, frame));
  StagedUpload triangles(context, packTriangles(bvh, frame));
  StagedUpload origins(context, bricks.originTable());
  const uint64_t chunkCells = uint64_t(std::min(slots, kSlotsPerChunk)) * brickCells;
  const gpu::GpuBuffer out(context, chunkCells * sizeof(float), Usage::eStorageBuffer, gpu::MemoryUse::Readback);

  using T = vk::DescriptorType;
  gpu::ComputeProgram& program = distanceProgram(context);
  const vk::DescriptorPoolSize poolSize(T::eStorageBuffer, 4);
  vk::raii::DescriptorPool pool(
      context.device(),
      vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, poolSize));
  vk::raii::DescriptorSets sets(context.device(), vk::DescriptorSetAllocateInfo(*pool, *program.setLayout));
  const vk::DescriptorBufferInfo nodeInfo(nodes.target.handle(), 0, VK_WHOLE_SIZE),
      triangleInfo(triangles.target.handle(), 0, VK_WHOLE_SIZE), originInfo(origins.target.handle(), 0, VK_WHOLE_SIZE),
      outInfo(out.handle(), 0, VK_WHOLE_SIZE);
  context.device().updateDescriptorSets(
      {vk::WriteDescriptorSet(*sets[0], BAND_DISTANCE_BINDING_NODES, 0, T::eStorageBuffer, {}, nodeInfo),
       vk::WriteDescriptorSet(*sets[0], BAND_DISTANCE_BINDING_TRIANGLES, 0, T::eStorageBuffer, {}, triangleInfo),
       vk::WriteDescriptorSet(*sets[0], BAND_DISTANCE_BINDING_ORIGINS, 0, T::eStorageBuffer, {}, originInfo),
       vk::WriteDescriptorSet(*sets[0], BAND_DISTANCE_BINDING_DISTANCES, 0, T::eStorageBuffer, {}, outInfo)},
      {});

  const Extent3& e = bricks.cells();
  const double bound = std::min(maxVoxels, 1e18);  // squared, still a finite float; +inf beyond
  shader::Parameters push{0, 0, e.nx, e.ny, e.nz, std::isfinite(maxVoxels) ? float(bound * bound) : infinity};
  for (int first = 0; first < slots; first += kSlotsPerChunk) {
    interrupt::check("nothing was written");
    push.firstSlot = first, push.slots = std::min(kSlotsPerChunk, slots - first);
    const uint32_t groups = uint32_t(push.slots) * brickCells / BAND_DISTANCE_WORKGROUP_SIZE;
    context.runAndWait([&](vk::CommandBuffer cmd) {
      if (first == 0) {
        for (const StagedUpload* upload : {&nodes, &triangles, &origins}) upload->record(cmd);
        const vk::MemoryBarrier toShader(vk::AccessFlagBits::eTransferWrite, vk::AccessFlagBits::eShaderRead);
        cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eComputeShader, {},
                            toShader, {}, {});
      }
      cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
      cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, *sets[0], {});
      cmd.pushConstants<shader::Parameters>(*program.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
      cmd.dispatch(groups, 1, 1);
      const vk::MemoryBarrier toHost(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eHostRead);
      cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eHost, {}, toHost, {},
                          {});
    });
    if (first == 0)
      for (StagedUpload* upload : {&nodes, &triangles, &origins}) upload->release();
    std::memcpy(distance.data() + size_t(first) * brickCells, out.mapped(),
                size_t(push.slots) * brickCells * sizeof(float));
  }
  return distance;
}

}  // namespace lbmshape
