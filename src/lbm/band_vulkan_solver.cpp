#include "lbmshape/lbm/band_vulkan_solver.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstring>
#include <functional>
#include <numeric>

#include <glm/glm.hpp>

#include "lbmshape/shaders/band_interface.h"
#include "lbmshape/core/parallel_copy.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/memory_sizes.hpp"
#include "lbmshape/gpu/gpu_buffer.hpp"
#include "lbmshape/gpu/gpu_context.hpp"
#include "lbmshape/gpu/staged_copies.hpp"
#include "lbmshape/lbm/adaptive_gamma.hpp"
#include "lbmshape/lbm/band_state.hpp"
#include "lbmshape/lbm/band_surface_pass.hpp"
#include "lbmshape/lbm/d3q19.hpp"
#include "lbmshape/lbm/frozen_bricks.hpp"
#include "lbmshape/lbm/relaxation.hpp"
#include "lbmshape/lbm/solver_state.hpp"
#include "lbmshape/lbm/surface_change.hpp"

namespace lbmshape {

using gpu::GpuBuffer;
using gpu::MemoryUse;

namespace {

// Steps recorded into one submission; Ctrl-C is checked between batches by
// the caller (InterruptibleSteps), so this only bounds a command buffer.
constexpr int stepsPerSubmit = 256;

constexpr uint64_t momentBytesPerSlot = 4 * brickCells * 4, fieldBytesPerSlot = brickCells * 4;

constexpr auto texels = vk::BufferUsageFlagBits::eUniformTexelBuffer | vk::BufferUsageFlagBits::eTransferDst;
// The omega buffer: read as a uniform texel buffer (one view spans the
// whole band), written (the feature rule, the paper's rule) through storage
// buffers pooled as the field's (BAND_BINDING_OMEGA_OUT).
constexpr auto perCell = texels | vk::BufferUsageFlagBits::eStorageBuffer;
constexpr auto speedPartials = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc |
                               vk::BufferUsageFlagBits::eTransferDst;
constexpr auto storage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eUniformTexelBuffer |
                         vk::BufferUsageFlagBits::eTransferDst | vk::BufferUsageFlagBits::eTransferSrc;

// The neighbours' table as the shaders read it (band_interface.h): for each
// slot and each (dy, dz), the bricks at dx = -1, 0 and 1, and a 0.
std::vector<glm::ivec4> rowNeighbourTable(const BrickSet& bricks)
{
  const std::vector<int32_t> around = bricks.neighbourTable();  // (dx + 1) + 3 (dy + 1) + 9 (dz + 1)
  std::vector<glm::ivec4> table(around.size() / 3);
  for (size_t i = 0; i < table.size(); ++i)
    table[i] = glm::ivec4(around[3 * i], around[3 * i + 1], around[3 * i + 2], 0);
  return table;
}

std::vector<vk::DescriptorSetLayoutBinding> bindings()
{
  using T = vk::DescriptorType;
  return {{BAND_BINDING_MOMENTS, T::eUniformTexelBuffer, 1, {}},
          {BAND_BINDING_STREAMS, T::eUniformTexelBuffer, 1, {}},
          {BAND_BINDING_NEIGHBOURS, T::eUniformTexelBuffer, 1, {}},
          {BAND_BINDING_ORIGINS, T::eUniformTexelBuffer, 1, {}},
          {BAND_BINDING_OMEGA, T::eUniformTexelBuffer, 1, {}},
          {BAND_BINDING_SOURCE, T::eUniformTexelBuffer, 1, {}},
          {BAND_BINDING_NEXT, T::eStorageBuffer, BAND_MAX_POOLS, {}},
          {BAND_BINDING_FIELD, T::eStorageBuffer, BAND_MAX_FIELD_POOLS, {}},
          {BAND_BINDING_WORK, T::eUniformTexelBuffer, 1, {}},
          {BAND_BINDING_OMEGA_OUT, T::eStorageBuffer, BAND_MAX_FIELD_POOLS, {}}};
}

gpu::ProgramSpec speedProgram()
{
  using T = vk::DescriptorType;
  return {"band_speed",
          {{BAND_SPEED_BINDING_NEWER, T::eUniformTexelBuffer, 1, {}},
           {BAND_SPEED_BINDING_OLDER, T::eUniformTexelBuffer, 1, {}},
           {BAND_SPEED_BINDING_PARTIALS, T::eStorageBuffer, 1, {}}},
          {},
          sizeof(band_shader::SpeedParameters)};
}

}  // namespace

// How the band's buffers split into pools of whole bricks, each within the
// device's storage-buffer range.
struct BandPools {
  BandPools(const gpu::DeviceDescription& device, size_t slots, uint64_t poolBytes)
      : slotsPerMomentPool(std::max<uint64_t>(1, range(device, poolBytes) / momentBytesPerSlot)),
        slotsPerFieldPool(std::max<uint64_t>(1, range(device, poolBytes) / fieldBytesPerSlot))
  {
    const uint64_t cells = uint64_t(slots) * brickCells;
    const uint64_t most =
        std::min(BandVulkanSolver::maxCells(device, false, false),
                 std::min(BAND_MAX_POOLS * slotsPerMomentPool, BAND_MAX_FIELD_POOLS * slotsPerFieldPool) * brickCells);
    if (cells > most)
      throw DeviceError("the narrow band has " + std::to_string(cells) + " cells, but " + device.name +
                        " holds at most " + std::to_string(most) + " of them");
  }
  static uint64_t range(const gpu::DeviceDescription& device, uint64_t poolBytes)
  {
    return poolBytes ? std::min(poolBytes, device.maxStorageBufferRange) : device.maxStorageBufferRange;
  }

  uint64_t slotsPerMomentPool, slotsPerFieldPool;
};

struct BandVulkanSolver::Resources {
  Resources(gpu::GpuContext& c, std::shared_ptr<const BrickSet> b, uint64_t stagingBytes, uint64_t poolBytes)
      : context(c), bricks(std::move(b)), cells(bricks->storedCells()), frozen(bricks->activeCount()),
        pools(c.description(), bricks->activeCount(), poolBytes), moments{GpuBuffer(c, 16 * cells, storage,
                                                                                    MemoryUse::Device),
                                                                          GpuBuffer(c, 16 * cells, storage,
                                                                                    MemoryUse::Device)},
        field(c, 16, storage, MemoryUse::Device), streams(c, 4 * 64 * bricks->activeCount(), texels, MemoryUse::Device),
        neighbours(c, 16 * 9 * bricks->activeCount(), texels, MemoryUse::Device),
        origins(c, 16 * bricks->activeCount(), texels, MemoryUse::Device),
        work(c, 4 * 3 * bricks->activeCount(), texels, MemoryUse::Device), omega(c, 16, perCell, MemoryUse::Device),
        source(c, 16, texels, MemoryUse::Device), partials(c, 16, speedPartials, MemoryUse::Device),
        copies(c, std::clamp<uint64_t>(stagingBytes, momentBytesPerSlot, momentBytesPerSlot * bricks->activeCount())),
        surface(c, copies)
  {
    std::array<vk::DescriptorPoolSize, 2> sizes = {
        vk::DescriptorPoolSize(vk::DescriptorType::eUniformTexelBuffer, 4 * 7),
        vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 4 * (BAND_MAX_POOLS + 2 * BAND_MAX_FIELD_POOLS))};
    descriptorPool = vk::raii::DescriptorPool(
        c.device(), vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 4, sizes));
    // The feature rule's layout is the steps' (the same bindings): whichever
    // kind of step the run makes, no other pipeline is made for it.
    const auto& setLayout = c.program(featureRuleProgram()).setLayout;
    std::vector<vk::DescriptorSetLayout> layouts(4, *setLayout);
    sets = vk::raii::DescriptorSets(c.device(), vk::DescriptorSetAllocateInfo(*descriptorPool, layouts));
    writeDescriptors();
  }

  gpu::GpuContext& context;
  std::shared_ptr<const BrickSet> bricks;
  size_t cells;
  FrozenBricks frozen;
  BandPools pools;
  GpuBuffer moments[2];
  // The field buffer: 16 bytes until field() needs it (fullFieldBuffer()), so
  // that a smoothing whose result comes from the moments (storedField)
  // never holds it while it runs.
  GpuBuffer field;
  GpuBuffer streams, neighbours, origins;
  // The work lists, one after the other: the slots a step updates in full,
  // those it holds whole (setHeldBricks), then every slot split alike, for
  // the field pass; frozen slots in none. band_step.comp runs the first of
  // each pair, band_hold.comp the second. From 2 * slots on, the slots of
  // one freezing or catch-up pass (extraList()).
  GpuBuffer work;
  struct WorkRange {
    int offset = 0, count = 0;
  };
  WorkRange stepRange, heldRange, fieldRange, heldFieldRange;
  std::vector<int32_t> stepSlots;  // the slots a step updates (band_state::slotsToStep)
  std::vector<uint8_t> heldSlots;  // per slot, a BrickMotion; empty: every brick streams
  // 16 bytes until set: a valid view for the shader variants that ignore
  // them. omega holds omega per cell, or under the paper's rule gamma per
  // cell, which the steps update.
  GpuBuffer omega, source;
  GpuBuffer partials;        // the surface-speed pass's sums per row (SurfaceChangeSums); its size once it is used
  gpu::StagedCopies copies;  // every upload and read-back, through its staging buffer
  BandSurfacePass surface;   // the frames' marching cubes (a morph's)
  std::vector<vk::raii::BufferView> views;
  vk::raii::DescriptorPool descriptorPool{nullptr};
  // [k]: reads copy k, writes the other; [2 + k]: reads and writes copy k
  // (a catch-up whose brick froze in the copy a step reads next).
  std::vector<vk::raii::DescriptorSet> sets;
  // The surface-speed pass's: [k] reads copy k as the newer, the other as
  // the older. Its own views: the moments buffers are never replaced.
  std::vector<vk::raii::BufferView> speedViews;
  vk::raii::DescriptorPool speedPool{nullptr};
  std::vector<vk::raii::DescriptorSet> speedSets;
  // Batches of steps, recorded once each (by count, first copy, slots, push
  // constants and pipeline) and replayed; writeDescriptors() clears them.
  gpu::RecordedCommandCache recordedSteps;

  int current = 0;
  int steps = 0;
  // The feature rule's scratch is the older copy of the moments: from the
  // step at which it ran until the next, only the current copy holds a state.
  int olderCopySpentAt = -1;
  // The steps whose states the two copies hold, as storedField() and
  // previousField() may go back.
  int stepsStored() const { return olderCopySpentAt < 0 ? steps : std::min(steps, 1 + steps - olderCopySpentAt); }
  float uniformOmega = 1.0f;
  bool perCellOmega = false;              // the omega buffer holds omega per cell
  std::optional<double> paperRuleGamma0;  // set: the steps apply the paper's rule
  bool paperRuleReady = false;            // initialize() has seeded its gamma
  std::optional<BandSource> sourceHost;
  BandField initial;            // X at initialisation (its values until the first step), with its far sides
  bool holdForRestart = false;  // initial keeps its values after the first step, for restart()
  bool workHasSource = false;   // whether the cells a step updates were chosen for a source

  vk::BufferView view(const GpuBuffer& buffer, vk::Format format)
  {
    views.emplace_back(context.device(), vk::BufferViewCreateInfo({}, buffer.handle(), format, 0, VK_WHOLE_SIZE));
    return *views.back();
  }

  // Descriptors of every binding, both sets; again when omega or the source
  // buffer is replaced.
  void writeDescriptors()
  {
    recordedSteps.clear();    // they bind these sets
    surface.readsReplaced();  // it reads the field and the source buffers too
    using T = vk::DescriptorType;
    views.clear();
    const vk::BufferView copyViews[2] = {view(moments[0], vk::Format::eR32G32B32A32Sfloat),
                                         view(moments[1], vk::Format::eR32G32B32A32Sfloat)};
    const vk::BufferView streamView = view(streams, vk::Format::eR32Uint),
                         neighbourView = view(neighbours, vk::Format::eR32G32B32A32Sint),
                         originView = view(origins, vk::Format::eR32G32B32A32Sint),
                         omegaView = view(omega, vk::Format::eR32G32B32A32Sfloat),
                         sourceView = view(source, vk::Format::eR32G32B32A32Sfloat),
                         workView = view(work, vk::Format::eR32Sint);
    auto poolRanges = [&](const GpuBuffer& buffer, uint64_t bytesPerSlot, uint64_t slotsPerPool, uint64_t count) {
      std::vector<vk::DescriptorBufferInfo> ranges(count);
      const uint64_t poolBytes = bytesPerSlot * slotsPerPool;
      for (uint64_t k = 0; k < count; ++k) {
        // Pools past the last repeat it: every descriptor must be valid.
        const uint64_t offset = std::min(k * poolBytes, (buffer.bytes() - 1) / poolBytes * poolBytes);
        ranges[k] = vk::DescriptorBufferInfo(buffer.handle(), offset, std::min(poolBytes, buffer.bytes() - offset));
      }
      return ranges;
    };
    const std::vector<vk::DescriptorBufferInfo> copyRanges[2] = {
        poolRanges(moments[0], momentBytesPerSlot, pools.slotsPerMomentPool, BAND_MAX_POOLS),
        poolRanges(moments[1], momentBytesPerSlot, pools.slotsPerMomentPool, BAND_MAX_POOLS)};
    const auto fieldRanges = poolRanges(field, fieldBytesPerSlot, pools.slotsPerFieldPool, BAND_MAX_FIELD_POOLS);
    const auto omegaRanges = poolRanges(omega, fieldBytesPerSlot, pools.slotsPerFieldPool, BAND_MAX_FIELD_POOLS);
    std::vector<vk::WriteDescriptorSet> writes;
    for (int k = 0; k < 4; ++k) {
      const vk::DescriptorSet set = *sets[size_t(k)];
      const int reads = k % 2, writesTo = k < 2 ? 1 - reads : reads;
      writes.emplace_back(set, BAND_BINDING_MOMENTS, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &copyViews[reads]);
      writes.emplace_back(set, BAND_BINDING_STREAMS, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &streamView);
      writes.emplace_back(set, BAND_BINDING_NEIGHBOURS, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &neighbourView);
      writes.emplace_back(set, BAND_BINDING_ORIGINS, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &originView);
      writes.emplace_back(set, BAND_BINDING_OMEGA, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &omegaView);
      writes.emplace_back(set, BAND_BINDING_SOURCE, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &sourceView);
      writes.emplace_back(set, BAND_BINDING_WORK, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &workView);
      writes.emplace_back(set, BAND_BINDING_NEXT, 0, BAND_MAX_POOLS, T::eStorageBuffer, nullptr,
                          copyRanges[size_t(writesTo)].data());
      writes.emplace_back(set, BAND_BINDING_FIELD, 0, BAND_MAX_FIELD_POOLS, T::eStorageBuffer, nullptr,
                          fieldRanges.data());
      writes.emplace_back(set, BAND_BINDING_OMEGA_OUT, 0, BAND_MAX_FIELD_POOLS, T::eStorageBuffer, nullptr,
                          omegaRanges.data());
    }
    context.device().updateDescriptorSets(writes, {});
  }

  // A new device buffer, its pages touched by a fill: on lavapipe a
  // shader's first stores into pages never touched cost several times a
  // fill (the feature rule's pass at --res 128: 8 ms more; the fill of the
  // same 2.7 MB, 1 ms).
  GpuBuffer filledBuffer(uint64_t bytes, vk::BufferUsageFlags usage)
  {
    GpuBuffer buffer(context, bytes, usage, MemoryUse::Device);
    context.runAndWait([&](vk::CommandBuffer cmd) { cmd.fillBuffer(buffer.handle(), 0, VK_WHOLE_SIZE, 0u); });
    return buffer;
  }

  // Made on the first surfaceSpeed(): a morph never asks for it, and
  // lavapipe compiles every pipeline it creates.
  void writeSpeedDescriptors()
  {
    if (!speedSets.empty()) return;
    partials = filledBuffer(sizeof(glm::vec4) * 64 * bricks->activeCount(), speedPartials);
    using T = vk::DescriptorType;
    const std::array<vk::DescriptorPoolSize, 2> sizes = {vk::DescriptorPoolSize(T::eUniformTexelBuffer, 2 * 2),
                                                         vk::DescriptorPoolSize(T::eStorageBuffer, 2)};
    speedPool = vk::raii::DescriptorPool(
        context.device(), vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 2, sizes));
    const auto& setLayout = context.program(speedProgram()).setLayout;
    const std::vector<vk::DescriptorSetLayout> layouts(2, *setLayout);
    speedSets = vk::raii::DescriptorSets(context.device(), vk::DescriptorSetAllocateInfo(*speedPool, layouts));
    for (const GpuBuffer& copy : moments)
      speedViews.emplace_back(
          context.device(),
          vk::BufferViewCreateInfo({}, copy.handle(), vk::Format::eR32G32B32A32Sfloat, 0, VK_WHOLE_SIZE));
    const vk::DescriptorBufferInfo partialsInfo(partials.handle(), 0, VK_WHOLE_SIZE);
    std::vector<vk::WriteDescriptorSet> writes;
    for (size_t k = 0; k < 2; ++k) {
      const vk::DescriptorSet set = *speedSets[k];
      writes.emplace_back(set, BAND_SPEED_BINDING_NEWER, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr,
                          &*speedViews[k]);
      writes.emplace_back(set, BAND_SPEED_BINDING_OLDER, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr,
                          &*speedViews[1 - k]);
      writes.emplace_back(set, BAND_SPEED_BINDING_PARTIALS, 0, 1, T::eStorageBuffer, nullptr, &partialsInfo);
    }
    context.device().updateDescriptorSets(writes, {});
  }

  // `out` on this band's bricks with its far value and sides, its memory
  // kept where it already is (a morph's recycled frame).
  void shapeLikeTheBand(BandField& out) const
  {
    const bool same = out.sharedBricks() == initial.sharedBricks() && out.farValue() == initial.farValue() &&
                      out.values().size() == cells && out.farSides() == initial.farSides();
    if (!same) out = initial.sameShape();
  }

  // The field buffer at its full size, one float a stored cell.
  void fullFieldBuffer()
  {
    if (field.bytes() == 4 * cells) return;
    // Read back at every frame of a morph: on lavapipe straight from where
    // the device wrote it (a 44 MB copy into the staging buffer and one out
    // of it, each frame, at 256^3, became the second alone).
    field = GpuBuffer(context, 4 * cells, storage, MemoryUse::DeviceReadByHost);
    writeDescriptors();
  }

  // The surface's pieces of the field that `before` writes into the field
  // buffer (BandSurfacePass::list).
  SurfacePieces listSurface(const SurfaceRequest& request, const std::function<void(vk::CommandBuffer)>& before,
                            const std::function<void()>& ran)
  {
    fullFieldBuffer();
    return surface.list(request, {field, neighbours, origins, source, initial, sourceHost.has_value()}, before, ran);
  }

  // The parameters of the next step made to also store the field it pulls
  // (the frame's, under the source it had), with Cs `next` from then on:
  // fieldIntoThenStep()'s and surfacePiecesThenStep()'s one pass. None where
  // that cannot be one pass: before the first step (whose field is the
  // initial one), where a step leaves bricks out or some freeze now, under
  // the paper's rule.
  std::optional<band_shader::StepParameters> stepStoringItsField(std::optional<SourceStrength> next)
  {
    const bool stepsEveryBrick =
        size_t(stepRange.count + heldRange.count) + frozen.frozenCount() == bricks->activeCount();
    if (steps == 0 || !stepsEveryBrick || paperRuleGamma0 || frozen.freezingNext()) return std::nullopt;
    fullFieldBuffer();
    const band_shader::StepParameters before = parameters(false);
    if (next) SteppingSolver::setStrength(sourceHost, next->decay, next->scale);
    band_shader::StepParameters push = parameters(false);
    frozen.beforeSteps(1, frozenStepParameters(), steps, current);  // freezes none (above)
    push.writeField = 1;
    push.fieldDecay = before.decay;
    push.fieldBaseScale = before.baseScale;
    return push;
  }

  // The omega buffer at its full size, one float a stored cell.
  void perCellBuffer()
  {
    if (omega.bytes() == 4 * cells) return;
    omega = filledBuffer(4 * cells, perCell);
    writeDescriptors();
  }

  // The one pipeline of every step and field pass of the run's kind: the
  // source and the paper's rule are specialization constants
  // (band_step.glsl), what differs within a run push constants
  // (parameters()).
  gpu::ProgramSpec program() const { return program(kindOfRun()); }
  static gpu::ProgramSpec program(BandRunKind kind) { return ofKind("band_step", kind); }
  // The held bricks' pipeline: band_step.comp's arithmetic, no fetch from
  // any other cell.
  gpu::ProgramSpec holdProgram() const { return ofKind("band_hold", kindOfRun()); }
  BandRunKind kindOfRun() const { return {sourceHost.has_value(), paperRuleGamma0.has_value()}; }
  static gpu::ProgramSpec ofKind(const char* shader, BandRunKind kind)
  {
    using gpu::specBool;
    using gpu::specFloat;
    return {shader,
            bindings(),
            {specFloat(d3q19::restWeight), specFloat(d3q19::axialWeight), specFloat(d3q19::diagonalWeight),
             specBool(kind.source), specBool(kind.paperRule)},
            sizeof(band_shader::StepParameters)};
  }

  // The feature-preserving rule's pipeline: a shader of its own, where a
  // pass of band_step.comp would run the whole step's code masked.
  gpu::ProgramSpec featureRuleProgram() const
  {
    return {"band_feature_rule", bindings(), {}, sizeof(band_shader::StepParameters)};
  }

  // The work lists for stepSlots and heldSlots, on the device.
  void uploadWork()
  {
    std::vector<int32_t> every(bricks->activeCount()), lists;
    std::iota(every.begin(), every.end(), 0);
    lists.reserve(2 * every.size());
    const auto append = [&](WorkRange& range, const std::vector<int32_t>& slots, bool held) {
      range.offset = int(lists.size());
      for (int32_t s : slots)
        if (!frozen.frozen(size_t(s)) && (!heldSlots.empty() && heldSlots[size_t(s)] != 0) == held) lists.push_back(s);
      range.count = int(lists.size()) - range.offset;
    };
    append(stepRange, stepSlots, false);
    append(heldRange, stepSlots, true);
    append(fieldRange, every, false);
    append(heldFieldRange, every, true);
    copies.upload(lists.data(), lists.size() * 4, work);
  }

  // `slots` as the work list of one pass, after the lists uploadWork() makes.
  WorkRange extraList(const std::vector<int32_t>& slots)
  {
    const WorkRange range{int(2 * bricks->activeCount()), int(slots.size())};
    copies.upload(slots.data(), slots.size() * 4, work, uint64_t(range.offset) * 4);
    return range;
  }

  // What the catch-up of frozen bricks needs to know of the steps to come.
  FrozenBricks::StepParameters frozenStepParameters() const
  {
    return {sourceHost.has_value(),
            sourceHost ? sourceHost->decay : 0.0f,
            sourceHost ? sourceHost->scale : 1.0f,
            uniformOmega,
            perCellOmega,
            paperRuleGamma0.has_value()};
  }

  // Before `count` steps: the bricks that freeze now get their field (X of
  // the state they freeze with), and leave the work lists.
  void freezeBeforeSteps(int count)
  {
    const std::vector<int32_t> freezing = frozen.beforeSteps(count, frozenStepParameters(), steps, current);
    if (freezing.empty()) return;
    const gpu::TraceLabel label("band bricks freezing");
    fullFieldBuffer();
    band_shader::StepParameters push = parameters(true);
    const WorkRange range = extraList(freezing);
    push.workOffset = range.offset;
    push.works = range.count;
    // Its own submission: the next one's first barrier (GpuContext::recordInto)
    // makes what it wrote visible.
    context.runAndWait([&](vk::CommandBuffer cmd) { dispatch(cmd, context.program(holdProgram()), current, push); });
    uploadWork();
  }

  // A step's parameters, or with `everySlot` the field pass's, for the
  // slots band_step.comp updates.
  band_shader::StepParameters parameters(bool everySlot) const
  {
    const Extent3& e = bricks->cells();
    band_shader::StepParameters p{};
    p.nx = e.nx, p.ny = e.ny, p.nz = e.nz;
    p.workOffset = everySlot ? fieldRange.offset : stepRange.offset;
    p.works = everySlot ? fieldRange.count : stepRange.count;
    p.slotsPerMomentPool = int(pools.slotsPerMomentPool);
    p.slotsPerFieldPool = int(pools.slotsPerFieldPool);
    p.omega = uniformOmega;
    p.decay = sourceHost ? sourceHost->decay : 0.0f;
    p.baseScale = sourceHost ? sourceHost->scale : 1.0f;
    p.gamma0 = float(paperRuleGamma0.value_or(0.0));
    p.pass = everySlot ? BAND_PASS_FIELD : BAND_PASS_STEP;
    p.perCellOmega = perCellOmega ? 1 : 0;
    return p;
  }

  // A dispatch over `push.works` bricks through descriptor set `set` (0 or
  // 1: reading that copy and writing the other; 2 or 3: reading and writing
  // copy set - 2).
  void dispatch(vk::CommandBuffer cmd, const gpu::ComputeProgram& program, int set,
                const band_shader::StepParameters& push) const
  {
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
    cmd.pushConstants<band_shader::StepParameters>(*program.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, *sets[size_t(set)], {});
    const auto works = uint32_t(push.works);
    cmd.dispatch(std::min<uint32_t>(works, BAND_MAX_WORKGROUPS_X),
                 (works + BAND_MAX_WORKGROUPS_X - 1) / BAND_MAX_WORKGROUPS_X, 1);
  }

  // A step from copy `from` (`push` from parameters(false)), or the field
  // pass (parameters(true)): band_step.comp over its slots, band_hold.comp
  // over the held ones.
  void recordPass(vk::CommandBuffer cmd, int from, band_shader::StepParameters push)
  {
    const bool fieldPass = push.pass == BAND_PASS_FIELD;
    dispatch(cmd, context.program(program()), from, push);
    const WorkRange& held = fieldPass ? heldFieldRange : heldRange;
    if (held.count == 0) return;
    // The two write different bricks, but both shaders may write the omega
    // buffer (the paper's rule) that both read: ordered for the validation
    // layer, which cannot see that they never meet.
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eComputeShader, {},
                        vk::MemoryBarrier(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eShaderRead), {}, {});
    push.workOffset = held.offset;
    push.works = held.count;
    dispatch(cmd, context.program(holdProgram()), from, push);
  }
};

BandVulkanSolver::BandVulkanSolver(gpu::GpuContext& context, std::shared_ptr<const BrickSet> bricks,
                                   uint64_t stagingBytes, BandRunKind kind, uint64_t poolBytes)
{
  const gpu::TraceLabel label("band set-up");
  if (bricks->activeCount() == 0) throw std::invalid_argument("a narrow band without bricks");
  r_ = std::make_unique<Resources>(context, std::move(bricks), stagingBytes, poolBytes);
  const BrickSet& b = *r_->bricks;
  const std::vector<glm::ivec4> table = rowNeighbourTable(b);
  r_->copies.upload(table.data(), table.size() * 16, r_->neighbours);
  const std::vector<glm::ivec4> origins = b.originTable();
  r_->copies.upload(origins.data(), origins.size() * 16, r_->origins);
  // Lavapipe turns a pipeline into machine code at its first dispatch (some
  // 250 ms on the 2-core host, where pipeline creation took 100): one
  // dispatch of no work here puts that in the set-up, where a real GPU's
  // driver compiles, rather than in the first step: the steps of the
  // run's kind, and the feature rule's (small, and the default denoise needs
  // it) or, for a morph, the held bricks'.
  band_shader::StepParameters idle = r_->parameters(false);
  idle.works = 0;
  const gpu::ProgramSpec second = kind.source ? Resources::ofKind("band_hold", kind) : r_->featureRuleProgram();
  context.runAndWait([&](vk::CommandBuffer cmd) {
    for (const gpu::ProgramSpec& spec : {Resources::program(kind), second}) {
      auto& program = context.program(spec);
      cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
      cmd.pushConstants<band_shader::StepParameters>(*program.layout, vk::ShaderStageFlagBits::eCompute, 0, idle);
      cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, *r_->sets[0], {});
      cmd.dispatch(1, 1, 1);
      // No cell is touched, but the validation layer counts the bindings
      // each shader may read and write: the rule writes the omega buffer
      // that the step reads.
      cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eComputeShader, {},
                          vk::MemoryBarrier(vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite,
                                            vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite),
                          {}, {});
    }
  });
}

BandVulkanSolver::~BandVulkanSolver() = default;

double BandVulkanSolver::deviceBytesPerCell(bool perCellOmega, bool source)
{
  // Per brick: streaming bits, neighbours, origin, work lists, the speed's
  // partials (a vec4 a row).
  const double tables = double(4 * 64 + 16 * 9 + 16 + 4 * 3 + 16 * 64) / brickCells;
  return 2 * 16 + 4 + tables + (perCellOmega ? 4 : 0) + (source ? 4 : 0);  // moments, field
}

uint64_t BandVulkanSolver::maxCells(const gpu::DeviceDescription& device, bool perCellOmega, bool source)
{
  const uint64_t slotsPerPool = std::max<uint64_t>(1, device.maxStorageBufferRange / momentBytesPerSlot);
  uint64_t most = std::min<uint64_t>(BAND_MAX_POOLS * slotsPerPool * brickCells, device.maxTexelBufferElements);
  if (device.maxAllocationBytes) most = std::min<uint64_t>(most, device.maxAllocationBytes / 16);
  if (device.deviceLocalBytes) {
    const uint64_t room =
        device.deviceLocalBytes > defaultStagingBytes ? device.deviceLocalBytes - defaultStagingBytes : 0;
    most = std::min<uint64_t>(most, uint64_t(double(room) / deviceBytesPerCell(perCellOmega, source)));
  }
  return most / brickCells * brickCells;
}

int BandVulkanSolver::longestSideThatFits(const BrickSet& bricks, const gpu::DeviceDescription& device,
                                          bool perCellOmega, bool source)
{
  // The band's cells grow with the surface's area: as the square of the
  // grid's longest side.
  return lbmshape::longestSideThatFits(bricks.cells(), double(bricks.storedCells()),
                                       double(maxCells(device, perCellOmega, source)), 2.0);
}

void BandVulkanSolver::checkFits(const BrickSet& bricks, const gpu::DeviceDescription& device, bool perCellOmega,
                                 bool source, int cap)
{
  const uint64_t cells = bricks.storedCells();
  const uint64_t most = maxCells(device, perCellOmega, source);
  if (cells <= most) return;
  const Extent3 e = bricks.cells();
  const double perCell = deviceBytesPerCell(perCellOmega, source);
  throw DeviceError("the narrow band of this " + e.toString() + " grid needs " + std::to_string(cells) + " cells (" +
                    mebibytes(uint64_t(double(cells) * perCell)) + ") but " + device.name + " holds at most " +
                    std::to_string(most) + " (" + mebibytes(uint64_t(double(most) * perCell)) + "); " +
                    gridThatWouldFit(e, double(cells), double(most), 2.0, cap));
}

std::string BandVulkanSolver::backendName() const { return "vulkan band (" + r_->context.description().name + ")"; }
const BrickSet& BandVulkanSolver::bricks() const { return *r_->bricks; }
int BandVulkanSolver::stepsTaken() const { return r_->steps; }

void BandVulkanSolver::setUniformGamma(double gamma)
{
  relaxation::checkGamma(gamma);
  r_->uniformOmega = float(relaxation::omegaFromGamma(gamma));
  r_->perCellOmega = false;
  r_->paperRuleGamma0.reset();
}

void BandVulkanSolver::setPaperRule(double gamma0)
{
  setUniformGamma(gamma0);
  r_->paperRuleGamma0 = gamma0;
  r_->paperRuleReady = false;
  r_->perCellBuffer();
}

void BandVulkanSolver::setGammaPerCell(const BandField& gamma)
{
  const gpu::TraceLabel label("band gamma upload");
  band_state::checkSameBricks(*r_->bricks, gamma, "gamma");
  const std::vector<float> omega = band_state::omegaFromGamma(gamma);
  r_->perCellOmega = true;
  r_->paperRuleGamma0.reset();
  r_->perCellBuffer();
  r_->copies.upload(omega.data(), 4 * r_->cells, r_->omega);
}

void BandVulkanSolver::setFeaturePreservingGamma(double gamma0, double kappaEdge)
{
  const gpu::TraceLabel label("band feature rule");
  // Before the first step the field is the host's, which initialize() got.
  if (r_->steps == 0) return BandSolver::setFeaturePreservingGamma(gamma0, kappaEdge);
  adaptive_gamma::checkFeatureRule(gamma0, kappaEdge);
  if (r_->heldRange.count > 0) throw std::logic_error("the feature rule runs on no held bricks");
  r_->perCellBuffer();
  // In one submission: the field into the older copy of the moments, then
  // the rule, which reads it there (through the other descriptor set) and
  // writes omega per cell. The rule reads its cells' neighbours, so it
  // cannot write where it reads; the older copy is its scratch, where a
  // buffer of its own would add a float a cell to the peak (47 MB at
  // --res 512). Both passes run over the bricks a step updates (85 % of
  // them at 512): the others' cells only ever pull from themselves, so
  // omega is never read there, and both copies of their moments still hold
  // the field they started with, which the rule reads as their X (with a
  // source every brick is updated).
  auto& program = r_->context.program(r_->program());
  auto& rule = r_->context.program(r_->featureRuleProgram());
  band_shader::StepParameters push = r_->parameters(false);
  auto shaderWritten = [](vk::CommandBuffer cmd, vk::PipelineStageFlags next, vk::AccessFlags access) {
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, next, {},
                        vk::MemoryBarrier(vk::AccessFlagBits::eShaderWrite, access), {}, {});
  };
  r_->context.runAndWait([&](vk::CommandBuffer cmd) {
    push.pass = BAND_PASS_FIELD_TO_OLDER;
    r_->dispatch(cmd, program, r_->current, push);
    shaderWritten(cmd, vk::PipelineStageFlagBits::eComputeShader, vk::AccessFlagBits::eShaderRead);
    push.gamma0 = float(gamma0);
    push.kappaEdge = float(kappaEdge);
    push.lowestGamma = float(std::min(adaptive_gamma::lowest, gamma0));
    r_->dispatch(cmd, rule, 1 - r_->current, push);
    // The next step reads omega, and writes the older copy the rule read.
    shaderWritten(cmd, vk::PipelineStageFlagBits::eComputeShader,
                  vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite);
  });
  r_->perCellOmega = true;
  r_->paperRuleGamma0.reset();
  r_->olderCopySpentAt = r_->steps;
}

void BandVulkanSolver::setSource(std::optional<BandSource> source)
{
  const gpu::TraceLabel label("band source upload");
  if (source) {
    band_state::checkSameBricks(*r_->bricks, source->base, "source");
    if (r_->source.bytes() != 4 * r_->cells) {
      r_->source = GpuBuffer(r_->context, 4 * r_->cells, texels, MemoryUse::Device);
      r_->writeDescriptors();
    }
    r_->copies.upload(source->base.values().data(), 4 * r_->cells, r_->source);
  }
  r_->sourceHost = std::move(source);
}

void BandVulkanSolver::setSourceStrength(float decay, float scale) { setStrength(r_->sourceHost, decay, scale); }

void BandVulkanSolver::setHeldBricks(std::vector<uint8_t> heldPerSlot)
{
  band_state::checkHeldBricks(heldPerSlot, *r_->bricks);
  // The bricks that thaw catch up, each group in one held step from the
  // copy it froze in to the one the next step reads.
  for (const FrozenBricks::CatchUp& group : r_->frozen.setMotion(heldPerSlot, r_->steps)) {
    const gpu::TraceLabel label("band bricks thawing");
    band_shader::StepParameters push = r_->parameters(false);
    const Resources::WorkRange range = r_->extraList(group.slots);
    push.workOffset = range.offset;
    push.works = range.count;
    push.decay = push.baseScale = group.decay;
    push.omega = group.omega;
    push.perCellOmega = 0;
    const int set = group.copy == r_->current ? 2 + r_->current : group.copy;
    // Held steps of a uniform omega, without the paper's rule.
    const gpu::ProgramSpec hold = Resources::ofKind("band_hold", {.source = r_->sourceHost.has_value()});
    r_->context.runAndWait([&](vk::CommandBuffer cmd) { r_->dispatch(cmd, r_->context.program(hold), set, push); });
  }
  r_->heldSlots = std::move(heldPerSlot);
  if (!r_->stepSlots.empty()) r_->uploadWork();
}

void BandVulkanSolver::initialize(BandField field, std::vector<uint8_t> streams)
{
  const gpu::TraceLabel label("band start");
  band_state::checkSameBricks(*r_->bricks, field, "field");
  solver_state::checkPaperRuleWithoutSource(r_->paperRuleGamma0.has_value(), r_->sourceHost.has_value());
  if (streams.size() != field.values().size()) throw std::invalid_argument("one streaming flag a stored cell");
  streams = band_state::onlyCellsInTheGrid(std::move(streams), *r_->bricks);
  r_->stepSlots = band_state::slotsToStep(*r_->bricks, streams, r_->sourceHost.has_value());
  r_->workHasSource = r_->sourceHost.has_value();
  r_->uploadWork();
  std::vector<uint32_t> rows(64 * r_->bricks->activeCount(), 0);
#pragma omp parallel for schedule(static)
  for (size_t row = 0; row < rows.size(); ++row)
    for (int x = 0; x < brickEdge; ++x) rows[row] |= uint32_t(streams[row * brickEdge + size_t(x)]) << x;
  r_->copies.upload(rows.data(), rows.size() * 4, r_->streams);
  startFrom(std::move(field));
}

void BandVulkanSolver::holdFieldForRestart() { r_->holdForRestart = true; }

void BandVulkanSolver::restart()
{
  const gpu::TraceLabel label("band restart");
  band_state::checkRestart(!r_->initial.values().empty(), r_->workHasSource, r_->sourceHost.has_value());
  solver_state::checkPaperRuleWithoutSource(r_->paperRuleGamma0.has_value(), r_->sourceHost.has_value());
  r_->holdForRestart = false;  // for one restart: the steps after it let the field go
  startFrom(std::move(r_->initial));
}

// The moments of `field` at equilibrium in both copies, and the paper's
// rule seeded: initialize() after the streaming cells are on the device.
void BandVulkanSolver::startFrom(BandField field)
{
  r_->surface.forgetTheStart();  // its far sides are the last start's
  if (r_->sourceHost && r_->sourceHost->base.values().size() != r_->cells)
    throw std::logic_error("a new start with a source needs setSource() again: its values go after the first step");
  if (r_->paperRuleGamma0 && r_->omega.bytes() != 4 * r_->cells)
    throw std::logic_error("the paper's rule starts without its gamma per cell");
  // rho* per brick (the first of its four moments, laid out [moment][cell])
  // built a chunk at a time in the staging buffer, j* = 0 filled on the
  // device: a quarter of the bytes cross from the host. Where they cross a
  // bus (GpuContext::copiesCrossABus) the staging holds whole slots, j* =
  // 0 written beside rho*, so that a chunk is one region: four times the
  // bytes, but one 2 KB region a brick took an NVIDIA H100 22 ms a chunk
  // of 16 MB (1 GB/s; 130 ms of a 311 ms lattice stage at --res 512). The
  // second copy is the first's, on the device (bricks a step skips keep
  // their moments in both), in the last chunk's submission. The paper's
  // rule starts from gamma0 in every cell, filled on the device too (a
  // buffer of it from the host and its submission were 2.5 ms of a 50 ms
  // lattice stage at --res 128 on lavapipe).
  const vk::MemoryBarrier transferWritten(vk::AccessFlagBits::eTransferWrite,
                                          vk::AccessFlagBits::eTransferWrite | vk::AccessFlagBits::eTransferRead);
  auto afterTransfers = [&](vk::CommandBuffer cmd) {
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eTransfer, {}, transferWritten,
                        {}, {});
  };
  const bool wholeSlots = r_->context.copiesCrossABus();
  const uint64_t unitBytes = wholeSlots ? momentBytesPerSlot : fieldBytesPerSlot, unitFloats = unitBytes / 4;
  r_->copies.uploadStrided(
      r_->moments[0], r_->bricks->activeCount(), unitBytes, momentBytesPerSlot,
      [&](uint64_t first, uint64_t count, std::byte* to) {
        float* out = reinterpret_cast<float*>(to);
#pragma omp parallel for schedule(static)
        for (uint64_t k = 0; k < count; ++k) {
          const size_t firstCell = size_t(first + k) * brickCells;
          float* slot = out + k * unitFloats;
          for (int l = 0; l < brickCells; ++l)
            slot[l] = band_state::collidedDensity(field, r_->sourceHost, firstCell + size_t(l));
          std::fill(slot + brickCells, slot + unitFloats, 0.0f);  // j* (nothing where only rho* goes)
        }
      },
      [&](vk::CommandBuffer cmd) {
        cmd.fillBuffer(r_->moments[0].handle(), 0, VK_WHOLE_SIZE, 0u);  // 0.0f
        if (r_->paperRuleGamma0)
          cmd.fillBuffer(r_->omega.handle(), 0, VK_WHOLE_SIZE, std::bit_cast<uint32_t>(float(*r_->paperRuleGamma0)));
        afterTransfers(cmd);
      },
      [&](vk::CommandBuffer cmd) {
        afterTransfers(cmd);
        cmd.copyBuffer(r_->moments[0].handle(), r_->moments[1].handle(), vk::BufferCopy(0, 0, r_->moments[0].bytes()));
      });
  r_->paperRuleReady = r_->paperRuleGamma0.has_value();

  r_->current = 0;
  r_->steps = 0;
  r_->olderCopySpentAt = -1;
  r_->frozen.start();
  r_->initial = std::move(field);
}

void BandVulkanSolver::step(int count)
{
  const gpu::TraceLabel label("band steps");
  requirePaperRuleInitialized(r_->paperRuleGamma0.has_value(), r_->paperRuleReady);
  // The state initialize() leaves is the one after the first step
  // (band_state::collidedEquilibrium): that step costs nothing.
  if (count > 0 && r_->steps == 0) --count, ++r_->steps;
  // Once a step is taken, field() makes every stored value on the device:
  // only the far sides of the initial field are still needed, unless it is
  // held for a restart.
  if (r_->steps > 0 && !r_->holdForRestart) {
    std::vector<float>().swap(r_->initial.values());
    // The source's base is on the device; the host's copy was for the
    // start's rho* (44 MB at a morph's 256^3).
    if (r_->sourceHost) std::vector<float>().swap(r_->sourceHost->base.values());
  }
  if (count <= 0) return;
  r_->freezeBeforeSteps(count);
  auto& program = r_->context.program(r_->program());
  while (count > 0) {
    const int batch = std::min(count, stepsPerSubmit);
    const int first = r_->current;
    const band_shader::StepParameters push = r_->parameters(false);
    const std::string key = gpu::keyOf(batch, first, r_->heldRange.offset, r_->heldRange.count, push,
                                       static_cast<VkPipeline>(*program.pipeline));
    r_->context.replayAndWait(r_->recordedSteps.get(r_->context, key, [&](vk::CommandBuffer cmd) {
      for (int s = 0; s < batch; ++s) {
        r_->recordPass(cmd, (first + s) % 2, push);
        // The next step reads what this one wrote and overwrites what it read.
        cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eComputeShader, {},
                            vk::MemoryBarrier(vk::AccessFlagBits::eShaderWrite | vk::AccessFlagBits::eShaderRead,
                                              vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite),
                            {}, {});
      }
    }));
    r_->current = (r_->current + batch) % 2;
    r_->steps += batch;
    count -= batch;
  }
}

BandField BandVulkanSolver::previousField()
{
  requireTwoSteps();
  if (r_->stepsStored() < 2) throw std::logic_error("the field before the feature rule is no longer stored");
  r_->current = 1 - r_->current;
  BandField out = field();
  r_->current = 1 - r_->current;
  return out;
}

BandField BandVulkanSolver::storedField(int back)
{
  const gpu::TraceLabel label("band stored field read-back");
  band_state::checkStoredField(back, r_->stepsStored(), r_->sourceHost.has_value());
  // Moment 0 of every brick of the copy: the first quarter of each slot.
  const GpuBuffer& copy = r_->moments[back == 1 ? r_->current : 1 - r_->current];
  BandField out = r_->initial.sameShape();
  r_->copies.downloadUnits(
      copy, r_->bricks->activeCount(), fieldBytesPerSlot, momentBytesPerSlot, out.values().data(),
      [](vk::CommandBuffer cmd) {
        cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eTransfer, {},
                            vk::MemoryBarrier(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eTransferRead), {},
                            {});
      },
      r_->context.copiesCrossABus());
  return out;
}

double BandVulkanSolver::surfaceSpeed()
{
  const gpu::TraceLabel label("band surface speed");
  band_state::checkStoredField(2, r_->stepsStored(), r_->sourceHost.has_value());
  r_->writeSpeedDescriptors();
  const uint32_t slots = uint32_t(r_->bricks->activeCount());
  std::vector<glm::vec4> partials(size_t(slots) * 64);
  auto& program = r_->context.program(speedProgram());
  r_->copies.download(r_->partials, r_->partials.bytes(), partials.data(), [&](vk::CommandBuffer cmd) {
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eComputeShader, {},
                        vk::MemoryBarrier(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eShaderRead), {}, {});
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, *r_->speedSets[size_t(r_->current)],
                           {});
    cmd.pushConstants<band_shader::SpeedParameters>(*program.layout, vk::ShaderStageFlagBits::eCompute, 0,
                                                    band_shader::SpeedParameters{int(slots)});
    cmd.dispatch(std::min<uint32_t>(slots, BAND_MAX_WORKGROUPS_X),
                 (slots + BAND_MAX_WORKGROUPS_X - 1) / BAND_MAX_WORKGROUPS_X, 1);
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eTransfer, {},
                        vk::MemoryBarrier(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eTransferRead), {}, {});
  });
  SurfaceChangeSums sums;
  for (const glm::vec4& row : partials) sums += SurfaceChangeSums{double(row.x), double(row.y), double(row.z)};
  return sums.speed();
}

BandField BandVulkanSolver::field()
{
  BandField out;
  fieldInto(out);
  return out;
}

void BandVulkanSolver::fieldIntoThenStep(BandField& out, std::optional<SourceStrength> next)
{
  const gpu::TraceLabel label("band step with its field");
  // One pass where the step updates every brick (a morph's: its source
  // moves the held cells too) and is a real one (the first is free, and
  // its field the initial one); the paper's rule is never used with a
  // source.
  // Frozen bricks are in no pass: their field stays what they froze with.
  // A brick that freezes at this step gets its field after the frame's
  // is read, as in the reference.
  const std::optional<band_shader::StepParameters> push = r_->stepStoringItsField(next);
  if (!push) {
    BandSolver::fieldIntoThenStep(out, next);
    return;
  }
  r_->shapeLikeTheBand(out);
  const int first = r_->current;
  r_->copies.download(r_->field, 4 * r_->cells, out.values().data(), [&](vk::CommandBuffer cmd) {
    r_->recordPass(cmd, first, *push);
    // The next step reads what this one wrote; the copy reads the field.
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader,
                        vk::PipelineStageFlagBits::eComputeShader | vk::PipelineStageFlagBits::eTransfer, {},
                        vk::MemoryBarrier(vk::AccessFlagBits::eShaderWrite | vk::AccessFlagBits::eShaderRead,
                                          vk::AccessFlagBits::eShaderRead | vk::AccessFlagBits::eShaderWrite |
                                              vk::AccessFlagBits::eTransferRead),
                        {}, {});
  });
  r_->current = 1 - first;
  r_->steps += 1;
}

void BandVulkanSolver::fieldInto(BandField& out)
{
  const gpu::TraceLabel label("band field read-back");
  // Beyond the band nothing moves: the far sides are the initial field's
  // (its values, kept until the first real step, are not copied).
  if (r_->steps == 0) {
    out = r_->initial;
    return;
  }
  r_->shapeLikeTheBand(out);
  r_->fullFieldBuffer();
  r_->copies.download(r_->field, 4 * r_->cells, out.values().data(), [&](vk::CommandBuffer cmd) {
    r_->recordPass(cmd, r_->current, r_->parameters(true));
    cmd.pipelineBarrier(vk::PipelineStageFlagBits::eComputeShader, vk::PipelineStageFlagBits::eTransfer, {},
                        vk::MemoryBarrier(vk::AccessFlagBits::eShaderWrite, vk::AccessFlagBits::eTransferRead), {}, {});
  });
}

SurfacePieces BandVulkanSolver::surfacePieces(const SurfaceRequest& request)
{
  const gpu::TraceLabel label("band surface pieces");
  // Before the first step the field is the initial one, whose values are kept.
  if (r_->steps == 0) return listSurfacePieces(r_->initial, request, r_->sourceHost ? &r_->sourceHost->base : nullptr);
  return r_->listSurface(
      request, [&](vk::CommandBuffer cmd) { r_->recordPass(cmd, r_->current, r_->parameters(true)); }, [] {});
}

SurfacePieces BandVulkanSolver::surfacePiecesThenStep(const SurfaceRequest& request, std::optional<SourceStrength> next)
{
  const gpu::TraceLabel label("band step with its surface pieces");
  // As fieldIntoThenStep(): one pass where the step stores the field, the
  // surface pass reading it.
  const std::optional<band_shader::StepParameters> push = r_->stepStoringItsField(next);
  if (!push) return BandSolver::surfacePiecesThenStep(request, next);
  const int first = r_->current;
  return r_->listSurface(
      request, [&](vk::CommandBuffer cmd) { r_->recordPass(cmd, first, *push); },
      [&] {
        r_->current = 1 - first;
        r_->steps += 1;
      });
}

}  // namespace lbmshape
