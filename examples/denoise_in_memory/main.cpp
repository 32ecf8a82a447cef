// Denoises a mesh that never touches a file: a sphere with noise along its
// normals, smoothed by lbmshape's lattice on the best Vulkan device, then
// measured. Prints one line and exits 0 when the result is a closed surface
// no farther from the unit sphere than the noise was.
//
//   denoise_in_memory [--res N]      (default 64)
#include <lbmshape/lbmshape.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace {

// The largest distance of a vertex from the unit sphere.
double farthestFromTheSphere(const lbmshape::TriangleMesh& mesh)
{
  double worst = 0.0;
  for (const glm::dvec3& p : mesh.positions) worst = std::max(worst, std::abs(glm::length(p) - 1.0));
  return worst;
}

}  // namespace

int main(int argc, char** argv)
{
  int resolution = 64;
  if (argc == 3 && std::strcmp(argv[1], "--res") == 0) resolution = std::atoi(argv[2]);
  try {
    const lbmshape::TriangleMesh noisy = lbmshape::addNormalNoise(lbmshape::icosphere(5), 0.3, 7);
    lbmshape::ComputeDevice device("", false);
    lbmshape::DenoiseOptions options;
    options.grid.resolution = resolution;
    const lbmshape::DenoiseResult result = lbmshape::denoiseMesh(noisy, "a noisy sphere", options, device);
    const double before = farthestFromTheSphere(noisy), after = farthestFromTheSphere(result.mesh);
    std::printf(
        "lbmshape %s on %s: %zu triangles in, %zu out, %d steps; farthest from the sphere %.4f before, %.4f after\n",
        lbmshape::libraryVersion(), result.report["device"].get<std::string>().c_str(), noisy.triangles.size(),
        result.mesh.triangles.size(), result.report["steps"].get<int>(), before, after);
    return !result.mesh.triangles.empty() && after < before ? 0 : 1;
  } catch (const lbmshape::Error& e) {
    std::fprintf(stderr, "denoise_in_memory: %s\n", e.what());
    return 1;
  }
}
