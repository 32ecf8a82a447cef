#include "lbmshape/lbm/vulkan_solver.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "lbmshape/core/error.hpp"
#include "lbmshape/shaders/lattice_interface.h"
#include "lbmshape/gpu/gpu_buffer.hpp"
#include "lbmshape/gpu/gpu_context.hpp"
#include "lbmshape/lbm/adaptive_gamma.hpp"
#include "lbmshape/lbm/d3q19.hpp"
#include "lbmshape/lbm/lattice_memory.hpp"
#include "lbmshape/lbm/relaxation.hpp"
#include "lbmshape/lbm/solver_state.hpp"

namespace lbmshape {

using gpu::GpuBuffer;
using gpu::MemoryUse;

namespace {

constexpr int groupCount = row_groups::count;
constexpr int stepsPerSubmit = 256;
constexpr uint32_t initWorkgroupSize = 64;
// Invocations per workgroup of the lattice passes. They run over the
// four-cell blocks of a z plane, so workgroups are full whatever the row
// length; larger workgroups cut lavapipe's per-workgroup cost (measured at
// 128^3 on a Xeon with the previous layout: 32 invocations 67.3 MLUPS, 64:
// 69.1, 128: 71.0, 256: 71.0; on an AMD EPYC with the row-grouped layout 64,
// 128 and 256 are the same within noise).
constexpr uint32_t latticeWorkgroupSize = 128;

// Binding numbers of lbm_init.comp.
enum InitBinding : uint32_t { InitDensity = 0, InitOut = 1 };

using lattice_shader::FeatureRuleParameters;
using lattice_shader::StepParameters;

uint32_t groups(uint64_t items, uint32_t perGroup) { return uint32_t((items + perGroup - 1) / perGroup); }

std::vector<vk::DescriptorSetLayoutBinding> latticeBindings()
{
  using T = vk::DescriptorType;
  return {
      {LATTICE_BINDING_IN, T::eUniformTexelBuffer, 1, {}},
      {LATTICE_BINDING_OMEGA, T::eUniformTexelBuffer, 1, {}},
      {LATTICE_BINDING_SOURCE, T::eUniformTexelBuffer, 1, {}},
      {LATTICE_BINDING_NEXT, T::eStorageBuffer, groupCount, {}},
      {LATTICE_BINDING_FIELD, T::eStorageBuffer, 1, {}},
      {LATTICE_BINDING_GAMMA, T::eStorageBuffer, 1, {}},
  };
}

std::vector<vk::DescriptorSetLayoutBinding> initBindings()
{
  using T = vk::DescriptorType;
  return {{InitDensity, T::eStorageBuffer, 1, {}}, {InitOut, T::eStorageBuffer, groupCount, {}}};
}

// Specialization constants 0..9 of shaders/lattice_layout.glsl and lattice.glsl
// (constant 1 is unused).
std::vector<uint32_t> gridConstants(const LatticeLayout& layout, uint32_t workgroupSize)
{
  using gpu::specFloat, gpu::specInt;
  const Extent3& e = layout.extent;
  return {workgroupSize,
          1,
          specInt(e.nx),
          specInt(e.ny),
          specInt(e.nz),
          specInt(layout.row),
          specFloat(d3q19::restWeight),
          specFloat(d3q19::axialWeight),
          specFloat(d3q19::diagonalWeight),
          specInt(int(layout.blocks))};
}

void barrier(vk::CommandBuffer cmd, vk::AccessFlags src, vk::PipelineStageFlags srcStage, vk::AccessFlags dst,
             vk::PipelineStageFlags dstStage)
{
  cmd.pipelineBarrier(srcStage, dstStage, {}, vk::MemoryBarrier(src, dst), {}, {});
}

constexpr auto shaderRead = vk::AccessFlagBits::eShaderRead;
constexpr auto shaderWrite = vk::AccessFlagBits::eShaderWrite;
constexpr auto computeStage = vk::PipelineStageFlagBits::eComputeShader;
constexpr auto transferStage = vk::PipelineStageFlagBits::eTransfer;

}  // namespace

struct VulkanSolver::Resources {
  Resources(gpu::GpuContext& c, const LatticeLayout& l);

  gpu::GpuContext& context;
  LatticeLayout layout;
  // The two lattice copies: a step reads one (through its texel view) and
  // writes the other.
  std::vector<GpuBuffer> lattice;
  std::vector<vk::raii::BufferView> latticeViews;
  GpuBuffer field, staging;
  GpuBuffer omega;  // omega per cell, or under the paper's rule gamma per cell, which the steps update
  GpuBuffer sourceBuffer;
  vk::raii::BufferView omegaView{nullptr}, sourceView{nullptr};
  vk::raii::DescriptorPool pool{nullptr};
  std::vector<vk::raii::DescriptorSet> latticeSets;  // [k]: reads copy k, writes the other
  vk::raii::DescriptorSet initSet{nullptr};
  // Batches of steps, recorded once each (by count, first copy, push
  // constants and pipeline: the relaxation's and source's variant) and
  // replayed; writeDescriptors() clears them.
  gpu::RecordedCommandCache recordedSteps;

  int current = 0;  // copy holding the latest post-collision distributions
  int steps = 0;
  float uniformOmega = 1.0f;
  bool perCellOmega = false;
  std::optional<double> paperRuleGamma0;  // set: the steps apply the paper's rule
  bool paperRuleReady = false;            // initialize() has seeded its gamma and X before
  std::optional<LinearSource> source;     // host copy: initialize() needs A

  gpu::ProgramSpec latticeProgram(const char* shader) const
  {
    auto constants = gridConstants(layout, latticeWorkgroupSize);
    constants.push_back(gpu::specBool(perCellOmega));
    constants.push_back(gpu::specBool(source.has_value()));
    constants.push_back(gpu::specBool(paperRuleGamma0.has_value()));
    return {shader, latticeBindings(), constants, sizeof(StepParameters)};
  }
  gpu::ProgramSpec featureRuleProgram() const
  {
    return {"lbm_feature_rule", latticeBindings(), gridConstants(layout, latticeWorkgroupSize),
            sizeof(FeatureRuleParameters)};
  }
  gpu::ProgramSpec initProgram() const
  {
    return {"lbm_init", initBindings(), gridConstants(layout, initWorkgroupSize), 0};
  }

  // Dispatches a lattice pipeline over every block of the grid.
  void dispatchLattice(vk::CommandBuffer cmd) const
  {
    const Extent3& e = layout.extent;
    cmd.dispatch(groups(uint64_t(layout.row / 4) * uint64_t(e.ny), latticeWorkgroupSize), 1, uint32_t(e.nz));
  }

  StepParameters parameters() const
  {
    return {uniformOmega,
            source ? source->decay : 0.0f,
            source ? source->scale : 1.0f,
            float(paperRuleGamma0.value_or(0.0)),
            0,
            0.0f,
            0.0f};
  }

  void upload(const Volume& values, GpuBuffer& target);
  // Records the copy of the field buffer into the staging buffer and the
  // barrier that lets the host read it (the caller's barrier before lets
  // the copy read what shaders wrote).
  void recordFieldToStaging(vk::CommandBuffer cmd) const;
  // The field in the staging buffer (lattice layout) into `out`, made the
  // grid's size where it is not.
  void unstageField(Volume& out) const;
  // The first half of upload: the values in the staging buffer, in the
  // lattice layout, for a copy recorded with others in one submission.
  void stage(const Volume& values);
  void writeDescriptors();
};

namespace {
GpuBuffer volumeBuffer(gpu::GpuContext& c, const LatticeLayout& l, vk::BufferUsageFlags usage, MemoryUse use)
{
  return GpuBuffer(c, l.volumeBytes, usage, use);
}
}  // namespace

VulkanSolver::Resources::Resources(gpu::GpuContext& c, const LatticeLayout& l)
    : context(c), layout(l),
      field(volumeBuffer(c, l,
                         vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc |
                             vk::BufferUsageFlagBits::eTransferDst,
                         MemoryUse::Device)),
      staging(volumeBuffer(c, l, vk::BufferUsageFlagBits::eTransferSrc | vk::BufferUsageFlagBits::eTransferDst,
                           MemoryUse::Readback)),
      omega(volumeBuffer(c, l,
                         vk::BufferUsageFlagBits::eUniformTexelBuffer | vk::BufferUsageFlagBits::eStorageBuffer |
                             vk::BufferUsageFlagBits::eTransferDst,
                         MemoryUse::Device)),
      sourceBuffer(volumeBuffer(c, l,
                                vk::BufferUsageFlagBits::eUniformTexelBuffer | vk::BufferUsageFlagBits::eTransferDst,
                                MemoryUse::Device))
{
  auto& device = context.device();
  const auto usage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eUniformTexelBuffer |
                     vk::BufferUsageFlagBits::eTransferDst;
  auto view = [&](vk::Buffer buffer, vk::Format format) {
    return vk::raii::BufferView(device, vk::BufferViewCreateInfo({}, buffer, format, 0, VK_WHOLE_SIZE));
  };
  for (int k = 0; k < 2; ++k) {
    lattice.emplace_back(context, layout.copyBytes, usage, MemoryUse::Device);
    latticeViews.push_back(view(lattice.back().handle(), vk::Format::eR32G32B32A32Sfloat));
  }
  omegaView = view(omega.handle(), vk::Format::eR32G32B32A32Sfloat);
  sourceView = view(sourceBuffer.handle(), vk::Format::eR32G32B32A32Sfloat);

  std::array<vk::DescriptorPoolSize, 2> sizes = {
      vk::DescriptorPoolSize(vk::DescriptorType::eUniformTexelBuffer, 2 * 3),
      vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 2 * (groupCount + 2) + (groupCount + 1))};
  pool = vk::raii::DescriptorPool(
      device, vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 3, sizes));
  auto allocate = [&](const vk::raii::DescriptorSetLayout& setLayout, uint32_t count) {
    std::vector<vk::DescriptorSetLayout> layouts(count, *setLayout);
    return vk::raii::DescriptorSets(device, vk::DescriptorSetAllocateInfo(*pool, layouts));
  };
  latticeSets = allocate(context.program(latticeProgram("lbm_step")).setLayout, 2);
  initSet = std::move(allocate(context.program(initProgram()).setLayout, 1).front());
  writeDescriptors();

  // Row padding is never read by a real cell, but zeros keep every value the
  // device computes finite and the runs reproducible.
  context.runAndWait([&](vk::CommandBuffer cmd) {
    for (auto& copy : lattice) cmd.fillBuffer(copy.handle(), 0, VK_WHOLE_SIZE, 0u);
  });
}

void VulkanSolver::Resources::writeDescriptors()
{
  recordedSteps.clear();  // they bind these sets
  std::vector<vk::WriteDescriptorSet> writes;
  std::array<vk::BufferView, 2> copyViews = {*latticeViews[0], *latticeViews[1]};
  std::array<std::array<vk::DescriptorBufferInfo, groupCount>, 2> groupRanges;  // [k][g]: group g of copy k
  for (int k = 0; k < 2; ++k)
    for (int g = 0; g < groupCount; ++g)
      groupRanges[k][g] =
          vk::DescriptorBufferInfo(lattice[k].handle(), layout.groupOffsetBytes(g), layout.groupBytes(g));
  vk::BufferView omegaHandle = *omegaView, sourceHandle = *sourceView;
  vk::DescriptorBufferInfo fieldInfo(field.handle(), 0, VK_WHOLE_SIZE), gammaInfo(omega.handle(), 0, VK_WHOLE_SIZE);
  using T = vk::DescriptorType;
  for (int k = 0; k < 2; ++k) {
    vk::DescriptorSet set = *latticeSets[k];
    writes.emplace_back(set, LATTICE_BINDING_IN, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &copyViews[k]);
    writes.emplace_back(set, LATTICE_BINDING_OMEGA, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &omegaHandle);
    writes.emplace_back(set, LATTICE_BINDING_SOURCE, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &sourceHandle);
    writes.emplace_back(set, LATTICE_BINDING_NEXT, 0, groupCount, T::eStorageBuffer, nullptr,
                        groupRanges[1 - k].data());
    writes.emplace_back(set, LATTICE_BINDING_FIELD, 0, 1, T::eStorageBuffer, nullptr, &fieldInfo);
    writes.emplace_back(set, LATTICE_BINDING_GAMMA, 0, 1, T::eStorageBuffer, nullptr, &gammaInfo);
  }
  writes.emplace_back(*initSet, InitDensity, 0, 1, T::eStorageBuffer, nullptr, &fieldInfo);
  writes.emplace_back(*initSet, InitOut, 0, groupCount, T::eStorageBuffer, nullptr, groupRanges[0].data());
  context.device().updateDescriptorSets(writes, {});
}

// Copies a volume into a device buffer in the lattice layout (padding zero).
void VulkanSolver::Resources::upload(const Volume& values, GpuBuffer& target)
{
  stage(values);
  context.runAndWait([&](vk::CommandBuffer cmd) {
    cmd.copyBuffer(staging.handle(), target.handle(), vk::BufferCopy(0, 0, layout.volumeBytes));
  });
}

void VulkanSolver::Resources::stage(const Volume& values)
{
  const Extent3& e = layout.extent;
  float* dst = reinterpret_cast<float*>(staging.mapped());
  std::memset(dst, 0, layout.volumeBytes);
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y)
      std::memcpy(dst + layout.linearIndex(0, y, z), values.data() + e.index(0, y, z), size_t(e.nx) * 4);
}

VulkanSolver::VulkanSolver(gpu::GpuContext& context, Extent3 extent)
{
  const gpu::TraceLabel label("grid set-up");
  LatticeLayout layout = latticeLayout(extent);
  checkFitsDevice(layout, context.description());
  r_ = std::make_unique<Resources>(context, layout);
}

VulkanSolver::~VulkanSolver() = default;

std::string VulkanSolver::backendName() const { return "vulkan (" + r_->context.description().name + ")"; }
Extent3 VulkanSolver::extent() const { return r_->layout.extent; }
int VulkanSolver::stepsTaken() const { return r_->steps; }

void VulkanSolver::setUniformGamma(double gamma)
{
  relaxation::checkGamma(gamma);
  r_->uniformOmega = float(relaxation::omegaFromGamma(gamma));
  r_->perCellOmega = false;
  r_->paperRuleGamma0.reset();
}

void VulkanSolver::setGammaPerCell(const Volume& gamma)
{
  const gpu::TraceLabel label("grid gamma upload");
  solver_state::checkSameExtent(extent(), gamma.extent(), "gamma");
  r_->upload(solver_state::omegaFromGammaVolume(gamma), r_->omega);
  r_->perCellOmega = true;
  r_->paperRuleGamma0.reset();
}

void VulkanSolver::setFeaturePreservingGamma(double gamma0, double kappaEdge)
{
  const gpu::TraceLabel label("grid feature rule");
  adaptive_gamma::checkFeatureRule(gamma0, kappaEdge);
  // The rule replaces the paper's (whose X before the field pass would
  // overwrite) and any gamma per cell.
  r_->paperRuleGamma0.reset();
  auto& fieldProgram = r_->context.program(r_->latticeProgram("lbm_field"));
  auto& rule = r_->context.program(r_->featureRuleProgram());
  const StepParameters push = r_->parameters();
  const FeatureRuleParameters rulePush{float(gamma0), float(kappaEdge),
                                       float(std::min(adaptive_gamma::lowest, gamma0))};
  const auto bind = vk::PipelineBindPoint::eCompute;
  // In one submission and on the device: the field pass into the field
  // buffer, then the rule from there into the omega buffer.
  r_->context.runAndWait([&](vk::CommandBuffer cmd) {
    cmd.bindPipeline(bind, *fieldProgram.pipeline);
    cmd.pushConstants<StepParameters>(*fieldProgram.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
    cmd.bindDescriptorSets(bind, *fieldProgram.layout, 0, *r_->latticeSets[r_->current], {});
    r_->dispatchLattice(cmd);
    barrier(cmd, shaderWrite, computeStage, shaderRead, computeStage);
    cmd.bindPipeline(bind, *rule.pipeline);
    cmd.pushConstants<FeatureRuleParameters>(*rule.layout, vk::ShaderStageFlagBits::eCompute, 0, rulePush);
    cmd.bindDescriptorSets(bind, *rule.layout, 0, *r_->latticeSets[r_->current], {});
    r_->dispatchLattice(cmd);
    // The next step reads omega.
    barrier(cmd, shaderWrite, computeStage, shaderRead | shaderWrite, computeStage);
  });
  r_->perCellOmega = true;
}

void VulkanSolver::setPaperRule(double gamma0)
{
  setUniformGamma(gamma0);
  r_->paperRuleGamma0 = gamma0;
  r_->paperRuleReady = false;
}

void VulkanSolver::setSource(std::optional<LinearSource> source)
{
  const gpu::TraceLabel label("grid source upload");
  if (source) {
    solver_state::checkSameExtent(extent(), source->base.extent(), "source");
    r_->upload(source->base, r_->sourceBuffer);
  }
  r_->source = std::move(source);
}

void VulkanSolver::setSourceStrength(float decay, float scale) { setStrength(r_->source, decay, scale); }

void VulkanSolver::initialize(const Volume& fieldValues)
{
  const gpu::TraceLabel label("grid start");
  solver_state::checkSameExtent(extent(), fieldValues.extent(), "field");
  solver_state::checkPaperRuleWithoutSource(r_->paperRuleGamma0.has_value(), r_->source.has_value());
  // The field buffer holds X at the start: under the paper's rule, the
  // first step's X before. One submission: the upload, the paper rule's
  // seed, the equilibrium and under the rule the first X before.
  r_->stage(solver_state::initialDensity(fieldValues, r_->source));
  auto& program = r_->context.program(r_->initProgram());
  auto& fieldProgram = r_->context.program(r_->latticeProgram("lbm_field"));
  const LatticeLayout& l = r_->layout;
  const StepParameters push = r_->parameters();
  r_->context.runAndWait([&](vk::CommandBuffer cmd) {
    cmd.copyBuffer(r_->staging.handle(), r_->field.handle(), vk::BufferCopy(0, 0, l.volumeBytes));
    if (r_->paperRuleGamma0) {
      // gamma0 in every cell, the rows' padding too (whose X before and X
      // are 0: a 0 there would make the rule divide by it).
      const float gamma0 = float(*r_->paperRuleGamma0);
      uint32_t bits;
      std::memcpy(&bits, &gamma0, 4);
      cmd.fillBuffer(r_->omega.handle(), 0, VK_WHOLE_SIZE, bits);
    }
    barrier(cmd, vk::AccessFlagBits::eTransferWrite, vk::PipelineStageFlagBits::eTransfer, shaderRead | shaderWrite,
            computeStage);
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, *r_->initSet, {});
    cmd.dispatch(groups(uint64_t(l.row), initWorkgroupSize), uint32_t(l.extent.ny), uint32_t(l.extent.nz));
    if (r_->paperRuleGamma0) {
      // The first step's X before is what it pulls, so that gamma0 is its
      // gamma: the field pass leaves that in the field buffer.
      barrier(cmd, shaderWrite | shaderRead, computeStage, shaderRead | shaderWrite, computeStage);
      cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *fieldProgram.pipeline);
      cmd.pushConstants<StepParameters>(*fieldProgram.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
      cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *fieldProgram.layout, 0, *r_->latticeSets[0], {});
      r_->dispatchLattice(cmd);
    }
  });
  r_->paperRuleReady = r_->paperRuleGamma0.has_value();
  r_->current = 0;
  r_->steps = 0;
  // The pipelines of the steps and of field() for this source and
  // relaxation are compiled now, in the job's set-up, and not during its
  // steps: lavapipe ends the process with SIGSEGV when an allocation fails
  // inside its shader compiler, and a job near its memory limit (ulimit -v)
  // is further from it now than once a morph's frame writer has started.
  r_->context.program(r_->latticeProgram("lbm_step"));
  r_->context.program(r_->latticeProgram("lbm_field"));
}

void VulkanSolver::step(int count)
{
  const gpu::TraceLabel label("grid steps");
  requirePaperRuleInitialized(r_->paperRuleGamma0.has_value(), r_->paperRuleReady);
  auto& program = r_->context.program(r_->latticeProgram("lbm_step"));
  const StepParameters push = r_->parameters();
  const auto bind = vk::PipelineBindPoint::eCompute;
  while (count > 0) {
    const int batch = std::min(count, stepsPerSubmit);
    const int first = r_->current;
    r_->context.replayAndWait(r_->recordedSteps.get(
        r_->context, gpu::keyOf(batch, first, push, static_cast<VkPipeline>(*program.pipeline)),
        [&](vk::CommandBuffer cmd) {
          cmd.bindPipeline(bind, *program.pipeline);
          cmd.pushConstants<StepParameters>(*program.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
          for (int s = 0; s < batch; ++s) {
            cmd.bindDescriptorSets(bind, *program.layout, 0, *r_->latticeSets[(first + s) % 2], {});
            r_->dispatchLattice(cmd);
            // The next step reads what this one wrote and overwrites what it read.
            barrier(cmd, shaderWrite | shaderRead, computeStage, shaderRead | shaderWrite, computeStage);
          }
        }));
    r_->current = (r_->current + batch) % 2;
    r_->steps += batch;
    count -= batch;
  }
}

Volume VulkanSolver::previousField()
{
  requireTwoSteps();
  r_->current = 1 - r_->current;
  Volume out = field();
  r_->current = 1 - r_->current;
  return out;
}

void VulkanSolver::Resources::recordFieldToStaging(vk::CommandBuffer cmd) const
{
  cmd.copyBuffer(field.handle(), staging.handle(), vk::BufferCopy(0, 0, layout.volumeBytes));
  barrier(cmd, vk::AccessFlagBits::eTransferWrite, transferStage, vk::AccessFlagBits::eHostRead,
          vk::PipelineStageFlagBits::eHost);
}

void VulkanSolver::Resources::unstageField(Volume& out) const
{
  const Extent3& e = layout.extent;
  if (out.extent() != e) out = Volume(e);
  const float* src = reinterpret_cast<const float*>(staging.mapped());
  // Every thread copies (one took longer than the device's whole read-back
  // at 256^3 on an H100).
#pragma omp parallel for schedule(static)
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y)
      std::memcpy(out.data() + e.index(0, y, z), src + layout.linearIndex(0, y, z), size_t(e.nx) * 4);
}

void VulkanSolver::fieldIntoThenStep(Volume& out, std::optional<SourceStrength> next)
{
  const gpu::TraceLabel label("grid step with its field");
  // Under the paper's rule the field buffer holds the rule's X before.
  if (r_->paperRuleGamma0) {
    LatticeSolver::fieldIntoThenStep(out, next);
    return;
  }
  auto& program = r_->context.program(r_->latticeProgram("lbm_step"));
  const StepParameters before = r_->parameters();
  if (next) setSourceStrength(next->decay, next->scale);
  StepParameters push = r_->parameters();
  push.writeField = 1;
  push.fieldDecay = before.decay;
  push.fieldBaseScale = before.baseScale;
  const int first = r_->current;
  r_->context.runAndWait([&](vk::CommandBuffer cmd) {
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
    cmd.pushConstants<StepParameters>(*program.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, *r_->latticeSets[first], {});
    r_->dispatchLattice(cmd);
    // The next step reads what this one wrote; the copy reads the field.
    barrier(cmd, shaderWrite | shaderRead, computeStage, shaderRead | shaderWrite | vk::AccessFlagBits::eTransferRead,
            computeStage | transferStage);
    r_->recordFieldToStaging(cmd);
  });
  r_->current = 1 - first;
  r_->steps += 1;
  r_->unstageField(out);
}

Volume VulkanSolver::field()
{
  Volume out;
  fieldInto(out);
  return out;
}

void VulkanSolver::fieldInto(Volume& out)
{
  const gpu::TraceLabel label("grid field read-back");
  auto& program = r_->context.program(r_->latticeProgram("lbm_field"));
  const LatticeLayout& l = r_->layout;
  // Under the paper's rule the field buffer holds the X the last step
  // pulled, which the next step needs: it is kept aside and put back.
  std::vector<std::byte> xBefore;
  if (r_->paperRuleGamma0) {
    xBefore.resize(l.volumeBytes);
    r_->context.runAndWait([&](vk::CommandBuffer cmd) {
      barrier(cmd, shaderWrite, computeStage, vk::AccessFlagBits::eTransferRead, transferStage);
      r_->recordFieldToStaging(cmd);
    });
    std::memcpy(xBefore.data(), r_->staging.mapped(), l.volumeBytes);
  }
  const StepParameters push = r_->parameters();
  r_->context.runAndWait([&](vk::CommandBuffer cmd) {
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
    cmd.pushConstants<StepParameters>(*program.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, *r_->latticeSets[r_->current], {});
    r_->dispatchLattice(cmd);
    barrier(cmd, shaderWrite, computeStage, vk::AccessFlagBits::eTransferRead, transferStage);
    r_->recordFieldToStaging(cmd);
  });
  r_->unstageField(out);
  if (!xBefore.empty()) {
    std::memcpy(r_->staging.mapped(), xBefore.data(), l.volumeBytes);
    r_->context.runAndWait([&](vk::CommandBuffer cmd) {
      cmd.copyBuffer(r_->staging.handle(), r_->field.handle(), vk::BufferCopy(0, 0, l.volumeBytes));
    });
  }
}

}  // namespace lbmshape
