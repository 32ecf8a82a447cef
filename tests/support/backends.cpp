#include "support/backends.hpp"

#include "lbmshape/lbm/reference_solver.hpp"
#include "lbmshape/lbm/vulkan_solver.hpp"

namespace lbmshape::testing {

std::unique_ptr<LatticeSolver> makeSolver(Backend backend, Extent3 extent)
{
  if (backend == Backend::Vulkan) return std::make_unique<VulkanSolver>(sharedGpu(), extent);
  return std::make_unique<ReferenceSolver>(extent);
}

std::string backendName(const ::testing::TestParamInfo<Backend>& info)
{
  return info.param == Backend::Vulkan ? "vulkan" : "reference";
}

}  // namespace lbmshape::testing
