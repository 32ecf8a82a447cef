// A compute pipeline with its descriptor set layout and pipeline layout.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan_raii.hpp>

namespace lbmshape::gpu {

struct ProgramSpec {
  std::string shader;                                    // name in the shader registry
  std::vector<vk::DescriptorSetLayoutBinding> bindings;  // stage is set to compute
  std::vector<uint32_t> specialization;                  // constant_id i gets word i
  uint32_t pushConstantBytes = 0;

  std::string key() const;  // identifies the compiled pipeline
};

// Specialization words for the three kinds of constants the shaders use.
inline uint32_t specInt(int v) { return uint32_t(v); }
inline uint32_t specBool(bool v) { return v ? VK_TRUE : VK_FALSE; }
uint32_t specFloat(float v);

struct ComputeProgram {
  ComputeProgram(const vk::raii::Device& device, const vk::raii::PipelineCache& cache, const ProgramSpec& spec);

  vk::raii::DescriptorSetLayout setLayout;
  vk::raii::PipelineLayout layout;
  vk::raii::Pipeline pipeline;
};

}  // namespace lbmshape::gpu
