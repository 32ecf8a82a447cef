#include "lbmshape/gpu/compute_program.hpp"

#include <bit>
#include <sstream>

#include "lbmshape/gpu/shader_registry.hpp"

namespace lbmshape::gpu {

uint32_t specFloat(float v) { return std::bit_cast<uint32_t>(v); }

std::string ProgramSpec::key() const
{
  std::ostringstream k;
  k << shader << '|' << pushConstantBytes;
  for (const auto& b : bindings) k << '|' << b.binding << ':' << int(b.descriptorType) << 'x' << b.descriptorCount;
  k << "|spec";
  for (uint32_t word : specialization) k << ':' << word;
  return k.str();
}

namespace {
vk::raii::DescriptorSetLayout makeSetLayout(const vk::raii::Device& device,
                                            std::vector<vk::DescriptorSetLayoutBinding> bindings)
{
  for (auto& b : bindings) b.stageFlags = vk::ShaderStageFlagBits::eCompute;
  return vk::raii::DescriptorSetLayout(device, vk::DescriptorSetLayoutCreateInfo({}, bindings));
}

vk::raii::PipelineLayout makeLayout(const vk::raii::Device& device, const vk::raii::DescriptorSetLayout& set,
                                    uint32_t pushBytes)
{
  vk::PushConstantRange range(vk::ShaderStageFlagBits::eCompute, 0, pushBytes);
  vk::DescriptorSetLayout sets[] = {*set};
  vk::PipelineLayoutCreateInfo info({}, sets);
  if (pushBytes) info.setPushConstantRanges(range);
  return vk::raii::PipelineLayout(device, info);
}

vk::raii::Pipeline makePipeline(const vk::raii::Device& device, const vk::raii::PipelineCache& cache,
                                const vk::raii::PipelineLayout& layout, const ProgramSpec& spec)
{
  std::span<const uint32_t> code = embeddedSpirv(spec.shader);
  vk::raii::ShaderModule module(device, vk::ShaderModuleCreateInfo({}, code.size_bytes(), code.data()));
  std::vector<vk::SpecializationMapEntry> entries;
  for (uint32_t i = 0; i < spec.specialization.size(); ++i)
    entries.emplace_back(i, uint32_t(i * sizeof(uint32_t)), sizeof(uint32_t));
  vk::SpecializationInfo specialization(entries, vk::ArrayProxyNoTemporaries<const uint32_t>(spec.specialization));
  vk::PipelineShaderStageCreateInfo stage({}, vk::ShaderStageFlagBits::eCompute, *module, "main", &specialization);
  return vk::raii::Pipeline(device, cache, vk::ComputePipelineCreateInfo({}, stage, *layout));
}
}  // namespace

ComputeProgram::ComputeProgram(const vk::raii::Device& device, const vk::raii::PipelineCache& cache,
                               const ProgramSpec& spec)
    : setLayout(makeSetLayout(device, spec.bindings)), layout(makeLayout(device, setLayout, spec.pushConstantBytes)),
      pipeline(makePipeline(device, cache, layout, spec))
{}

}  // namespace lbmshape::gpu
