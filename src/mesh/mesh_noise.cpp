#include "lbmshape/mesh/mesh_noise.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/number_text.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/mesh/mesh_validation.hpp"

namespace lbmshape {
namespace {

// std::normal_distribution and std::uniform_real_distribution differ between
// standard libraries; std::mt19937_64's sequence is fixed by the standard. So
// uniforms come straight from its bits, and Gaussians from Box-Muller.
class PortableGaussian {
public:
  explicit PortableGaussian(uint32_t seed) : engine_(seed) {}

  double operator()()
  {
    if (hasSpare_) {
      hasSpare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - uniform();  // in (0, 1]: log(u1) is finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    spare_ = radius * std::sin(2.0 * std::numbers::pi * u2);
    hasSpare_ = true;
    return radius * std::cos(2.0 * std::numbers::pi * u2);
  }

private:
  double uniform() { return double(engine_() >> 11) * 0x1.0p-53; }  // [0, 1), 53 random bits

  std::mt19937_64 engine_;
  double spare_ = 0;
  bool hasSpare_ = false;
};

}  // namespace

TriangleMesh addNormalNoise(const TriangleMesh& mesh, double sigmaInMeanEdgeLengths, uint32_t seed)
{
  if (!(std::isfinite(sigmaInMeanEdgeLengths) && sigmaInMeanEdgeLengths >= 0.0))
    throw UsageError("addNormalNoise: sigma " + numberText(sigmaInMeanEdgeLengths) +
                     " is not a finite number of 0 or more");
  requireWellFormed(mesh, "the mesh");
  TriangleMesh noisy;
  noisy.positions = mesh.positions;
  noisy.triangles = mesh.triangles;
  const double sigma = sigmaInMeanEdgeLengths * meanEdgeLength(mesh);
  const std::vector<glm::dvec3> normals = areaWeightedNormals(mesh);
  PortableGaussian gaussian(seed);
  // One draw per vertex, used or not, so that a vertex's displacement depends
  // only on its index and the seed.
  for (size_t i = 0; i < noisy.positions.size(); ++i) noisy.positions[i] += sigma * gaussian() * normals[i];
  return noisy;
}

}  // namespace lbmshape
