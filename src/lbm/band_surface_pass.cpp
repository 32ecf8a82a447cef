#include "lbmshape/lbm/band_surface_pass.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstring>
#include <stdexcept>

#include "lbmshape/shaders/band_interface.h"
#include "lbmshape/shaders/band_surface_interface.h"
#include "lbmshape/band/band_field.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parallel_copy.hpp"
#include "lbmshape/gpu/gpu_buffer.hpp"
#include "lbmshape/gpu/gpu_context.hpp"
#include "lbmshape/gpu/staged_copies.hpp"

namespace lbmshape {

using gpu::GpuBuffer;
using gpu::MemoryUse;

namespace {

gpu::ProgramSpec surfaceProgram()
{
  using T = vk::DescriptorType;
  return {"band_surface",
          {{SURFACE_BINDING_FIELD, T::eUniformTexelBuffer, 1, {}},
           {SURFACE_BINDING_NEIGHBOURS, T::eUniformTexelBuffer, 1, {}},
           {SURFACE_BINDING_ORIGINS, T::eUniformTexelBuffer, 1, {}},
           {SURFACE_BINDING_FAR_SIDES, T::eUniformTexelBuffer, 1, {}},
           {SURFACE_BINDING_BASE, T::eUniformTexelBuffer, 1, {}},
           {SURFACE_BINDING_COUNTERS, T::eStorageBuffer, 1, {}},
           {SURFACE_BINDING_CROSSINGS, T::eStorageBuffer, 1, {}},
           {SURFACE_BINDING_CUBES, T::eStorageBuffer, 1, {}},
           {SURFACE_BINDING_PROBES, T::eUniformTexelBuffer, 1, {}},
           {SURFACE_BINDING_PROBE_VALUES, T::eStorageBuffer, 1, {}}},
          {},
          sizeof(surface_shader::Parameters)};
}

// The device's records are SurfaceCrossing's and SurfaceCube's bytes (a
// little-endian 64-bit key or index in two words, then the rest as the
// structs lay it out): read back straight into the host's lists.
static_assert(sizeof(SurfaceCrossing) == 32 && offsetof(SurfaceCrossing, lower) == 8 &&
                  offsetof(SurfaceCrossing, upper) == 12 && offsetof(SurfaceCrossing, normal) == 16,
              "band_surface.comp's crossing records");
static_assert(sizeof(SurfaceCube) == 16 && offsetof(SurfaceCube, cubeCase) == 8 && offsetof(SurfaceCube, order) == 12,
              "band_surface.comp's cube records");
static_assert(std::endian::native == std::endian::little, "band_surface.comp's keys are two little-endian words");

// Per slot, the bits of band_surface_interface.h's SURFACE_BINDING_FAR_SIDES:
// which of the 27 bricks around it are not stored and inside.
std::vector<uint32_t> farSidesAround(const BandField& field)
{
  const BrickSet& bricks = field.bricks();
  std::vector<uint32_t> bits(bricks.activeCount(), 0u);
  for (size_t s = 0; s < bits.size(); ++s) {
    const glm::ivec3 b = bricks.brick(int32_t(s));
    for (int k = 0; k < 27; ++k) {
      const glm::ivec3 n = b + glm::ivec3(k % 3 - 1, k / 3 % 3 - 1, k / 9 - 1);
      if (bricks.bricks().contains(n.x, n.y, n.z) && bricks.slot(n.x, n.y, n.z) == noBrick &&
          field.farSide(n.x, n.y, n.z) > 0)
        bits[s] |= 1u << k;
    }
  }
  return bits;
}

constexpr auto surfaceTexels = vk::BufferUsageFlagBits::eUniformTexelBuffer | vk::BufferUsageFlagBits::eTransferDst;
constexpr auto surfaceLists = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc;

}  // namespace

// Made at the pass's first use after a start.
struct BandSurfacePass::Buffers {
  GpuBuffer farSides, counters, countersRead, crossings, cubes;
  // The probes' stored cells (those of a request's probes that are
  // stored, in order), and their values.
  GpuBuffer probes, probeValues;
  std::vector<glm::ivec3> probesAsked{};  // the request they were made for
  std::vector<int64_t> probeStored{};     // per probe asked: its stored cell, or -1
  std::vector<vk::raii::BufferView> views{};
  vk::raii::DescriptorPool pool{nullptr};
  vk::raii::DescriptorSets sets{nullptr};
};

BandSurfacePass::BandSurfacePass(gpu::GpuContext& context, gpu::StagedCopies& copies)
    : context_(context), copies_(copies)
{}

BandSurfacePass::~BandSurfacePass() = default;

// Here, where Buffers is complete (the header only declares it).
void BandSurfacePass::forgetTheStart() { buffers_.reset(); }

// The pass ready for lists of at least these lengths (which fit one
// storage-buffer binding: list()'s room), its set reading `reads` as they
// are now. What it replaces takes effect once all of it is made, so a
// failure leaves the pass as it was.
void BandSurfacePass::prepare(uint64_t crossings, uint64_t cubes, const std::vector<glm::ivec3>& probes,
                              const Reads& reads)
{
  using B = vk::BufferUsageFlagBits;
  if (!buffers_) {
    const std::vector<uint32_t> bits = farSidesAround(reads.start);
    auto made = std::make_unique<Buffers>(
        Buffers{GpuBuffer(context_, 4 * bits.size(), surfaceTexels, MemoryUse::Device),
                GpuBuffer(context_, 4 * SURFACE_COUNTERS, surfaceLists | B::eTransferDst, MemoryUse::Device),
                GpuBuffer(context_, 4 * SURFACE_COUNTERS, B::eTransferDst, MemoryUse::Readback),
                GpuBuffer(context_, 32 * std::max<uint64_t>(crossings, 1), surfaceLists, MemoryUse::DeviceReadByHost),
                GpuBuffer(context_, 16 * std::max<uint64_t>(cubes, 1), surfaceLists, MemoryUse::DeviceReadByHost),
                GpuBuffer(context_, 4, surfaceTexels, MemoryUse::Device),
                GpuBuffer(context_, 4, surfaceLists, MemoryUse::DeviceReadByHost)});
    copies_.upload(bits.data(), 4 * bits.size(), made->farSides);
    using T = vk::DescriptorType;
    const std::array<vk::DescriptorPoolSize, 2> sizes = {vk::DescriptorPoolSize(T::eUniformTexelBuffer, 6),
                                                         vk::DescriptorPoolSize(T::eStorageBuffer, 4)};
    made->pool = vk::raii::DescriptorPool(
        context_.device(),
        vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 1, sizes));
    const vk::DescriptorSetLayout layout = *context_.program(surfaceProgram()).setLayout;
    made->sets = vk::raii::DescriptorSets(context_.device(), vk::DescriptorSetAllocateInfo(*made->pool, layout));
    buffers_ = std::move(made);
    setStale_ = true;
  }
  Buffers& pass = *buffers_;
  if (probes != pass.probesAsked) {
    const BrickSet& bricks = reads.start.bricks();
    std::vector<int64_t> probeStored;
    std::vector<int32_t> stored;
    for (const glm::ivec3& c : probes) {
      if (!bricks.cells().contains(c.x, c.y, c.z)) throw std::invalid_argument("a probe beyond the grid");
      probeStored.push_back(bricks.storedIndex(c.x, c.y, c.z));
      if (probeStored.back() >= 0) stored.push_back(int32_t(probeStored.back()));
    }
    if (pass.probes.bytes() < 4 * stored.size()) {
      GpuBuffer cells(context_, 4 * stored.size(), surfaceTexels, MemoryUse::Device),
          values(context_, 4 * stored.size(), surfaceLists, MemoryUse::DeviceReadByHost);
      pass.probes = std::move(cells);
      pass.probeValues = std::move(values);
      setStale_ = true;
    }
    if (!stored.empty()) copies_.upload(stored.data(), 4 * stored.size(), pass.probes);
    pass.probeStored = std::move(probeStored);
    pass.probesAsked = probes;
  }
  if (pass.crossings.bytes() < 32 * crossings) {
    pass.crossings = GpuBuffer(context_, 32 * crossings, surfaceLists, MemoryUse::DeviceReadByHost);
    setStale_ = true;
  }
  if (pass.cubes.bytes() < 16 * cubes) {
    pass.cubes = GpuBuffer(context_, 16 * cubes, surfaceLists, MemoryUse::DeviceReadByHost);
    setStale_ = true;
  }
  if (setStale_) writeDescriptors(reads);
}

void BandSurfacePass::writeDescriptors(const Reads& reads)
{
  Buffers& pass = *buffers_;
  using T = vk::DescriptorType;
  std::vector<vk::raii::BufferView> views;
  const auto viewOf = [&](const GpuBuffer& buffer, vk::Format format) {
    views.emplace_back(context_.device(), vk::BufferViewCreateInfo({}, buffer.handle(), format, 0, VK_WHOLE_SIZE));
    return *views.back();
  };
  const vk::BufferView fieldView = viewOf(reads.field, vk::Format::eR32Sfloat),
                       neighbourView = viewOf(reads.neighbours, vk::Format::eR32G32B32A32Sint),
                       originView = viewOf(reads.origins, vk::Format::eR32G32B32A32Sint),
                       farView = viewOf(pass.farSides, vk::Format::eR32Uint),
                       baseView = viewOf(reads.sourceBase, vk::Format::eR32G32B32A32Sfloat),
                       probeView = viewOf(pass.probes, vk::Format::eR32Sint);
  const vk::DescriptorBufferInfo counterInfo(pass.counters.handle(), 0, VK_WHOLE_SIZE),
      crossingInfo(pass.crossings.handle(), 0, VK_WHOLE_SIZE), cubeInfo(pass.cubes.handle(), 0, VK_WHOLE_SIZE),
      probeValueInfo(pass.probeValues.handle(), 0, VK_WHOLE_SIZE);
  const vk::DescriptorSet set = *pass.sets[0];
  const std::vector<vk::WriteDescriptorSet> writes = {
      {set, SURFACE_BINDING_FIELD, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &fieldView},
      {set, SURFACE_BINDING_NEIGHBOURS, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &neighbourView},
      {set, SURFACE_BINDING_ORIGINS, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &originView},
      {set, SURFACE_BINDING_FAR_SIDES, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &farView},
      {set, SURFACE_BINDING_BASE, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &baseView},
      {set, SURFACE_BINDING_COUNTERS, 0, 1, T::eStorageBuffer, nullptr, &counterInfo},
      {set, SURFACE_BINDING_CROSSINGS, 0, 1, T::eStorageBuffer, nullptr, &crossingInfo},
      {set, SURFACE_BINDING_CUBES, 0, 1, T::eStorageBuffer, nullptr, &cubeInfo},
      {set, SURFACE_BINDING_PROBES, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &probeView},
      {set, SURFACE_BINDING_PROBE_VALUES, 0, 1, T::eStorageBuffer, nullptr, &probeValueInfo}};
  context_.device().updateDescriptorSets(writes, {});
  pass.views = std::move(views);
  setStale_ = false;
}

// Records the pass over the field buffer (which the commands before wrote)
// and the copy of its counters for the host.
void BandSurfacePass::record(vk::CommandBuffer cmd, const surface_shader::Parameters& push)
{
  Buffers& pass = *buffers_;
  cmd.fillBuffer(pass.counters.handle(), 0, VK_WHOLE_SIZE, 0u);
  cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eTransfer,
                      vk::PipelineStageFlagBits::eComputeShader, {},
                      vk::MemoryBarrier(vk::AccessFlagBits::eShaderWrite | vk::AccessFlagBits::eTransferWrite,
                                        vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite),
                      {}, {});
  const auto& program = context_.program(surfaceProgram());
  cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
  cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, *pass.sets[0], {});
  cmd.pushConstants<surface_shader::Parameters>(*program.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
  const auto slots = uint32_t(push.slots);
  cmd.dispatch(std::min<uint32_t>(slots, BAND_MAX_WORKGROUPS_X),
               (slots + BAND_MAX_WORKGROUPS_X - 1) / BAND_MAX_WORKGROUPS_X, 1);
  cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eTransfer, {},
                      vk::MemoryBarrier(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eTransferRead), {}, {});
  cmd.copyBuffer(pass.counters.handle(), pass.countersRead.handle(), vk::BufferCopy(0, 0, 4 * SURFACE_COUNTERS));
  cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer | vk::PipelineStageFlagBits::eComputeShader,
                      vk::PipelineStageFlagBits::eHost, {},
                      vk::MemoryBarrier(vk::AccessFlagBits::eTransferWrite | vk::AccessFlagBits::eShaderWrite,
                                        vk::AccessFlagBits::eHostRead),
                      {}, {});
}

SurfacePieces BandSurfacePass::list(const SurfaceRequest& request, const Reads& reads,
                                    const std::function<void(vk::CommandBuffer)>& before,
                                    const std::function<void()>& ran)
{
  const float isovalue = request.isovalue, nearBand = reads.hasSource ? request.nearBand : -1.0f;
  const uint64_t range = context_.description().maxStorageBufferRange;
  const uint64_t mostCrossings = std::min<uint64_t>(range / sizeof(SurfaceCrossing), INT32_MAX),
                 mostCubes = std::min<uint64_t>(range / sizeof(SurfaceCube), INT32_MAX);
  const auto room = [](uint64_t found, uint64_t most) { return std::min(found + found / 4 + 1024, most); };
  const BrickSet& bricks = reads.start.bricks();
  const uint64_t slots = bricks.activeCount();
  uint64_t crossingRoom = room(lastCrossings_ ? lastCrossings_ : 16 * slots, mostCrossings);
  uint64_t cubeRoom = room(lastCubes_ ? lastCubes_ : 16 * slots, mostCubes);
  for (bool first = true;; first = false) {
    prepare(crossingRoom, cubeRoom, request.probes, reads);
    const Extent3& e = bricks.cells();
    const auto storedProbes = int(std::count_if(buffers_->probeStored.begin(), buffers_->probeStored.end(),
                                                [](int64_t cell) { return cell >= 0; }));
    const surface_shader::Parameters push{
        e.nx,          e.ny,        e.nz, int(slots), isovalue, reads.start.farValue(), nearBand, int(crossingRoom),
        int(cubeRoom), storedProbes};
    context_.runAndWait([&](vk::CommandBuffer cmd) {
      if (first) before(cmd);
      record(cmd, push);
    });
    if (first) ran();
    std::array<uint32_t, SURFACE_COUNTERS> counts;
    std::memcpy(counts.data(), buffers_->countersRead.mapped(), sizeof(counts));
    if (counts[SURFACE_COUNTER_NOT_FINITE] > 0)
      throw NumericalError("the field holds a value that is not a finite number");
    const uint64_t crossings = counts[SURFACE_COUNTER_CROSSINGS], cubes = counts[SURFACE_COUNTER_CUBES];
    if (crossings > mostCrossings || cubes > mostCubes)
      throw DeviceError("the surface has " + std::to_string(crossings) + " cut grid edges and " +
                        std::to_string(cubes) + " cut cubes, more than one storage buffer of " +
                        context_.description().name + " holds (" + std::to_string(mostCrossings) + " and " +
                        std::to_string(mostCubes) + "); extract the frames on the CPU (--extract cpu)");
    if (crossings > crossingRoom || cubes > cubeRoom) {
      crossingRoom = std::max(crossingRoom, room(crossings, mostCrossings));
      cubeRoom = std::max(cubeRoom, room(cubes, mostCubes));
      continue;
    }
    lastCrossings_ = crossings;
    lastCubes_ = cubes;
    SurfacePieces pieces;
    pieces.extent = e;
    pieces.isovalue = isovalue;
    pieces.crossings.resize(crossings);
    pieces.cubes.resize(cubes);
    // The pass's submission ended with a barrier to host reads: a list
    // the host can see where it lies (lavapipe's) is copied at once, any
    // other through the staging buffer.
    const auto readList = [this](const GpuBuffer& list, uint64_t count, uint64_t unit, void* to) {
      if (count == 0) return;
      if (list.mapped())
        parallelCopy(static_cast<std::byte*>(to), list.mapped(), count * unit);
      else
        copies_.downloadUnits(list, count, unit, unit, to, [](vk::CommandBuffer) {});
    };
    readList(buffers_->crossings, crossings, sizeof(SurfaceCrossing), pieces.crossings.data());
    readList(buffers_->cubes, cubes, sizeof(SurfaceCube), pieces.cubes.data());
    std::vector<float> stored(static_cast<size_t>(storedProbes));
    readList(buffers_->probeValues, stored.size(), sizeof(float), stored.data());
    // A probe outside the stored bricks reads the far value on its side,
    // as BandField::at() does (the start keeps the far sides, not the values).
    for (size_t k = 0, next = 0; k < request.probes.size(); ++k) {
      const glm::ivec3 c = request.probes[k];
      pieces.probeValues.push_back(buffers_->probeStored[k] >= 0 ? stored[next++] : reads.start.at(c.x, c.y, c.z));
    }
    if (nearBand >= 0.0f) {
      float error;
      std::memcpy(&error, &counts[SURFACE_COUNTER_ERROR], sizeof(error));
      pieces.errorNearBase = error;
    }
    pieces.tidy();
    return pieces;
  }
}

}  // namespace lbmshape
