// Physics tests run on both back ends: the Vulkan solver users run, and the
// CPU reference that the other tests trust as the oracle.
#pragma once

#include <memory>
#include <string>

#include "lbmshape/lbm/lattice_solver.hpp"
#include "support/gpu_fixture.hpp"

namespace lbmshape::testing {

enum class Backend { Vulkan, Reference };

std::unique_ptr<LatticeSolver> makeSolver(Backend backend, Extent3 extent);
std::string backendName(const ::testing::TestParamInfo<Backend>& info);

// A GPU test (validation checked) parameterised by back end.
class BackendTest : public GpuTest, public ::testing::WithParamInterface<Backend> {
protected:
  std::unique_ptr<LatticeSolver> solver(Extent3 extent) { return makeSolver(GetParam(), extent); }
};

#define LBMSHAPE_ON_BOTH_BACKENDS(Suite)                                                                \
  INSTANTIATE_TEST_SUITE_P(                                                                             \
      Backends, Suite,                                                                                  \
      ::testing::Values(::lbmshape::testing::Backend::Vulkan, ::lbmshape::testing::Backend::Reference), \
      ::lbmshape::testing::backendName)

}  // namespace lbmshape::testing
