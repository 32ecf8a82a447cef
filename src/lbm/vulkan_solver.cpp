#include "lbm/vulkan_solver.hpp"

#include <array>
#include <cstring>

#include "core/error.hpp"
#include "gpu/gpu_buffer.hpp"
#include "gpu/gpu_context.hpp"
#include "lbm/d3q19.hpp"
#include "lbm/lattice_memory.hpp"
#include "lbm/relaxation.hpp"
#include "lbm/solver_state.hpp"

namespace lbmshape {

using d3q19::Q;
using gpu::GpuBuffer;
using gpu::MemoryUse;

namespace {

// Invocations per workgroup along x. Each handles four cells.
constexpr int workgroupSize = 64;
constexpr int stepsPerSubmit = 256;

// Binding numbers, as in shaders/lattice.glsl and shaders/lbm_*.comp.
enum LatticeBinding : uint32_t { InVec4 = 0, InScalar = 1, OmegaPerCell = 2, SourceBase = 3, OutVec4 = 4, FieldOut = 5 };
enum InitBinding : uint32_t { InitDensity = 0, InitOut = 1 };

struct PushConstants {
  float omega;
  float decay;
};

std::vector<vk::DescriptorSetLayoutBinding> latticeBindings()
{
  using T = vk::DescriptorType;
  return {
      {InVec4, T::eUniformTexelBuffer, Q, {}},  {InScalar, T::eUniformTexelBuffer, Q, {}},
      {OmegaPerCell, T::eUniformTexelBuffer, 1, {}}, {SourceBase, T::eUniformTexelBuffer, 1, {}},
      {OutVec4, T::eStorageBuffer, Q, {}},      {FieldOut, T::eStorageBuffer, 1, {}},
  };
}

std::vector<vk::DescriptorSetLayoutBinding> initBindings()
{
  using T = vk::DescriptorType;
  return {{InitDensity, T::eStorageBuffer, 1, {}}, {InitOut, T::eStorageBuffer, Q, {}}};
}

std::vector<uint32_t> gridConstants(const LatticeLayout& layout)
{
  using gpu::specFloat, gpu::specInt;
  const Extent3& e = layout.extent;
  return {specInt(workgroupSize), specInt(e.nx), specInt(e.ny), specInt(e.nz), specInt(layout.row),
          specFloat(d3q19::restWeight), specFloat(d3q19::axialWeight), specFloat(d3q19::diagonalWeight)};
}

void computeBarrier(vk::CommandBuffer cmd, vk::AccessFlags src, vk::PipelineStageFlags srcStage, vk::AccessFlags dst,
                    vk::PipelineStageFlags dstStage)
{
  vk::MemoryBarrier barrier(src, dst);
  cmd.pipelineBarrier(srcStage, dstStage, {}, barrier, {}, {});
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
  // lattice[k][i]: distribution i of lattice copy k; the step reads one copy
  // and writes the other.
  std::array<std::vector<GpuBuffer>, 2> lattice;
  std::array<std::vector<vk::raii::BufferView>, 2> vec4Views, scalarViews;
  GpuBuffer field, staging, omega, sourceBuffer;
  vk::raii::BufferView omegaView{nullptr}, sourceView{nullptr};
  vk::raii::DescriptorPool pool{nullptr};
  std::vector<vk::raii::DescriptorSet> latticeSets;  // [k]: reads copy k
  vk::raii::DescriptorSet initSet{nullptr};

  int current = 0;  // copy holding the latest post-collision distributions
  int steps = 0;
  float uniformOmega = 1.0f;
  bool perCellOmega = false;
  std::optional<LinearSource> source;  // host copy: initialize() needs A

  gpu::ProgramSpec latticeProgram(const char* shader) const
  {
    auto constants = gridConstants(layout);
    constants.push_back(gpu::specBool(perCellOmega));
    constants.push_back(gpu::specBool(source.has_value()));
    return {shader, latticeBindings(), constants, sizeof(PushConstants)};
  }

  void upload(const Volume& values, GpuBuffer& target);
  void writeDescriptors();
};

VulkanSolver::Resources::Resources(gpu::GpuContext& c, const LatticeLayout& l)
    : context(c),
      layout(l),
      field(c, l.paddedCells * 4,
            vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferSrc |
                vk::BufferUsageFlagBits::eTransferDst,
            MemoryUse::Device),
      staging(c, l.paddedCells * 4, vk::BufferUsageFlagBits::eTransferSrc | vk::BufferUsageFlagBits::eTransferDst,
              MemoryUse::Readback),
      omega(c, l.paddedCells * 4, vk::BufferUsageFlagBits::eUniformTexelBuffer | vk::BufferUsageFlagBits::eTransferDst,
            MemoryUse::Device),
      sourceBuffer(c, l.paddedCells * 4, vk::BufferUsageFlagBits::eUniformTexelBuffer | vk::BufferUsageFlagBits::eTransferDst,
             MemoryUse::Device)
{
  auto& device = context.device();
  const auto usage = vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eUniformTexelBuffer;
  for (int k = 0; k < 2; ++k) {
    for (int i = 0; i < Q; ++i) {
      lattice[k].emplace_back(context, layout.directionBytes, usage, MemoryUse::Device);
      vk::Buffer b = lattice[k].back().handle();
      vec4Views[k].emplace_back(device, vk::BufferViewCreateInfo({}, b, vk::Format::eR32G32B32A32Sfloat, 0, VK_WHOLE_SIZE));
      scalarViews[k].emplace_back(device, vk::BufferViewCreateInfo({}, b, vk::Format::eR32Sfloat, 0, VK_WHOLE_SIZE));
    }
  }
  omegaView = vk::raii::BufferView(device, vk::BufferViewCreateInfo({}, omega.handle(), vk::Format::eR32G32B32A32Sfloat, 0, VK_WHOLE_SIZE));
  sourceView = vk::raii::BufferView(device, vk::BufferViewCreateInfo({}, sourceBuffer.handle(), vk::Format::eR32G32B32A32Sfloat, 0, VK_WHOLE_SIZE));

  std::array<vk::DescriptorPoolSize, 2> sizes = {
      vk::DescriptorPoolSize(vk::DescriptorType::eUniformTexelBuffer, 2 * (2 * Q + 2)),
      vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 2 * (Q + 1) + Q + 1)};
  pool = vk::raii::DescriptorPool(device, vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, 3, sizes));
  auto& latticeLayoutHandle = context.program(latticeProgram("lbm_step")).setLayout;
  std::array<vk::DescriptorSetLayout, 2> latticeLayouts = {*latticeLayoutHandle, *latticeLayoutHandle};
  latticeSets = vk::raii::DescriptorSets(device, vk::DescriptorSetAllocateInfo(*pool, latticeLayouts));
  vk::DescriptorSetLayout initLayout = *context.program({"lbm_init", initBindings(), gridConstants(layout), 0}).setLayout;
  initSet = std::move(vk::raii::DescriptorSets(device, vk::DescriptorSetAllocateInfo(*pool, initLayout)).front());
  writeDescriptors();
}

void VulkanSolver::Resources::writeDescriptors()
{
  std::vector<vk::WriteDescriptorSet> writes;
  std::array<std::array<vk::BufferView, Q>, 2> vec4Handles, scalarHandles;
  std::array<std::array<vk::DescriptorBufferInfo, Q>, 2> outInfos;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < Q; ++i) {
      vec4Handles[k][i] = *vec4Views[k][i];
      scalarHandles[k][i] = *scalarViews[k][i];
      outInfos[k][i] = vk::DescriptorBufferInfo(lattice[k][i].handle(), 0, VK_WHOLE_SIZE);
    }
  vk::BufferView omegaHandle = *omegaView, sourceHandle = *sourceView;
  vk::DescriptorBufferInfo fieldInfo(field.handle(), 0, VK_WHOLE_SIZE);
  using T = vk::DescriptorType;
  for (int k = 0; k < 2; ++k) {
    vk::DescriptorSet set = *latticeSets[k];
    writes.emplace_back(set, InVec4, 0, Q, T::eUniformTexelBuffer, nullptr, nullptr, vec4Handles[k].data());
    writes.emplace_back(set, InScalar, 0, Q, T::eUniformTexelBuffer, nullptr, nullptr, scalarHandles[k].data());
    writes.emplace_back(set, OmegaPerCell, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &omegaHandle);
    writes.emplace_back(set, SourceBase, 0, 1, T::eUniformTexelBuffer, nullptr, nullptr, &sourceHandle);
    writes.emplace_back(set, OutVec4, 0, Q, T::eStorageBuffer, nullptr, outInfos[1 - k].data());
    writes.emplace_back(set, FieldOut, 0, 1, T::eStorageBuffer, nullptr, &fieldInfo);
  }
  writes.emplace_back(*initSet, InitDensity, 0, 1, T::eStorageBuffer, nullptr, &fieldInfo);
  writes.emplace_back(*initSet, InitOut, 0, Q, T::eStorageBuffer, nullptr, outInfos[0].data());
  context.device().updateDescriptorSets(writes, {});
}

// Copies a volume into a device buffer in the padded layout (padding zero).
void VulkanSolver::Resources::upload(const Volume& values, GpuBuffer& target)
{
  const Extent3& e = layout.extent;
  float* dst = reinterpret_cast<float*>(staging.mapped());
  std::memset(dst, 0, layout.paddedCells * 4);
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y)
      std::memcpy(dst + size_t(layout.row) * (size_t(y) + size_t(e.ny) * z), values.data() + e.index(0, y, z),
                  size_t(e.nx) * 4);
  context.runAndWait([&](vk::CommandBuffer cmd) {
    cmd.copyBuffer(staging.handle(), target.handle(), vk::BufferCopy(0, 0, layout.paddedCells * 4));
  });
}

VulkanSolver::VulkanSolver(gpu::GpuContext& context, Extent3 extent)
{
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
}

void VulkanSolver::setGammaPerCell(const Volume& gamma)
{
  solver_state::checkSameExtent(extent(), gamma.extent(), "gamma");
  r_->upload(solver_state::omegaFromGammaVolume(gamma), r_->omega);
  r_->perCellOmega = true;
}

void VulkanSolver::setSource(std::optional<LinearSource> source)
{
  if (source) {
    solver_state::checkSameExtent(extent(), source->base.extent(), "source");
    r_->upload(source->base, r_->sourceBuffer);
  }
  r_->source = std::move(source);
}

void VulkanSolver::initialize(const Volume& fieldValues)
{
  solver_state::checkSameExtent(extent(), fieldValues.extent(), "field");
  r_->upload(solver_state::initialDensity(fieldValues, r_->source), r_->field);
  auto& program = r_->context.program({"lbm_init", initBindings(), gridConstants(r_->layout), 0});
  const Extent3& e = r_->layout.extent;
  r_->context.runAndWait([&](vk::CommandBuffer cmd) {
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, *r_->initSet, {});
    cmd.dispatch(uint32_t((r_->layout.row + workgroupSize - 1) / workgroupSize), uint32_t(e.ny), uint32_t(e.nz));
  });
  r_->current = 0;
  r_->steps = 0;
}

void VulkanSolver::step(int count)
{
  auto& program = r_->context.program(r_->latticeProgram("lbm_step"));
  const Extent3& e = r_->layout.extent;
  const uint32_t groupsX = uint32_t((r_->layout.row / 4 + workgroupSize - 1) / workgroupSize);
  PushConstants push{r_->uniformOmega, r_->source ? r_->source->decay : 0.0f};
  while (count > 0) {
    int batch = std::min(count, stepsPerSubmit);
    r_->context.runAndWait([&](vk::CommandBuffer cmd) {
      cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
      cmd.pushConstants<PushConstants>(*program.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
      for (int s = 0; s < batch; ++s) {
        int reads = (r_->current + s) % 2;
        cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, *r_->latticeSets[reads], {});
        cmd.dispatch(groupsX, uint32_t(e.ny), uint32_t(e.nz));
        // The next step reads what this one wrote and overwrites what it read.
        computeBarrier(cmd, shaderWrite | shaderRead, computeStage, shaderRead | shaderWrite, computeStage);
      }
    });
    r_->current = (r_->current + batch) % 2;
    r_->steps += batch;
    count -= batch;
  }
}

Volume VulkanSolver::field()
{
  auto& program = r_->context.program(r_->latticeProgram("lbm_field"));
  const Extent3& e = r_->layout.extent;
  const uint32_t groupsX = uint32_t((r_->layout.row / 4 + workgroupSize - 1) / workgroupSize);
  PushConstants push{r_->uniformOmega, r_->source ? r_->source->decay : 0.0f};
  r_->context.runAndWait([&](vk::CommandBuffer cmd) {
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *program.pipeline);
    cmd.pushConstants<PushConstants>(*program.layout, vk::ShaderStageFlagBits::eCompute, 0, push);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *program.layout, 0, *r_->latticeSets[r_->current], {});
    cmd.dispatch(groupsX, uint32_t(e.ny), uint32_t(e.nz));
    computeBarrier(cmd, shaderWrite, computeStage, vk::AccessFlagBits::eTransferRead, transferStage);
    cmd.copyBuffer(r_->field.handle(), r_->staging.handle(), vk::BufferCopy(0, 0, r_->layout.paddedCells * 4));
    computeBarrier(cmd, vk::AccessFlagBits::eTransferWrite, transferStage, vk::AccessFlagBits::eHostRead,
                   vk::PipelineStageFlagBits::eHost);
  });
  Volume out(e);
  const float* src = reinterpret_cast<const float*>(r_->staging.mapped());
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y)
      std::memcpy(out.data() + e.index(0, y, z), src + size_t(r_->layout.row) * (size_t(y) + size_t(e.ny) * z),
                  size_t(e.nx) * 4);
  return out;
}

}  // namespace lbmshape
