// SPIR-V of the compute shaders in shaders/, compiled and embedded at build time.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace lbmshape::gpu {

std::span<const uint32_t> embeddedSpirv(std::string_view name);

}  // namespace lbmshape::gpu
