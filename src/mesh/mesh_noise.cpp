#include "lbmshape/mesh/mesh_noise.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/number_text.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/mesh/mesh_validation.hpp"
#include "lbmshape/mesh/vertex_welding.hpp"

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
  // Corners at one position move together, along the normal of all their
  // triangles: a soup's copies of a vertex (an STL's, an unwelded OBJ's)
  // each moved its own way, and the surface came apart in flakes.
  std::vector<glm::dvec3> corners;
  corners.reserve(3 * mesh.triangles.size());
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) corners.push_back(mesh.positions[t[k]]);
  const TriangleMesh joined = weldEqualPositions(corners);
  constexpr uint32_t unused = UINT32_MAX;
  std::vector<uint32_t> pointOf(mesh.positions.size(), unused);
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) pointOf[mesh.triangles[t][k]] = joined.triangles[t][k];
  const std::vector<glm::dvec3> normals = areaWeightedNormals(joined);
  // One draw per vertex, used or not, in index order, so that a vertex's
  // displacement depends only on its index and the seed; a point takes its
  // first vertex's.
  PortableGaussian gaussian(seed);
  std::vector<double> pointDraw(joined.positions.size(), std::numeric_limits<double>::quiet_NaN());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const double draw = gaussian();
    if (pointOf[i] != unused && std::isnan(pointDraw[pointOf[i]])) pointDraw[pointOf[i]] = draw;
  }
  for (size_t i = 0; i < noisy.positions.size(); ++i)
    if (pointOf[i] != unused) noisy.positions[i] += sigma * pointDraw[pointOf[i]] * normals[pointOf[i]];
  return noisy;
}

}  // namespace lbmshape
