#include "lbmshape/analysis/normal_noise.hpp"

#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include <gtest/gtest.h>

#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/mesh/mesh_noise.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

// Every triangle split into four at its edges' midpoints, which neighbours
// share: flat faces stay flat.
TriangleMesh subdivided(const TriangleMesh& mesh)
{
  TriangleMesh out;
  out.positions = mesh.positions;
  std::map<std::pair<unsigned, unsigned>, unsigned> midpoints;
  const auto midpoint = [&](unsigned a, unsigned b) {
    const auto key = std::minmax(a, b);
    const auto [at, added] = midpoints.try_emplace({key.first, key.second}, unsigned(out.positions.size()));
    if (added) out.positions.push_back(0.5 * (mesh.positions[a] + mesh.positions[b]));
    return at->second;
  };
  for (const glm::uvec3& t : mesh.triangles) {
    const unsigned ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    out.triangles.emplace_back(t[0], ab, ca);
    out.triangles.emplace_back(ab, t[1], bc);
    out.triangles.emplace_back(ca, bc, t[2]);
    out.triangles.emplace_back(ab, bc, ca);
  }
  return out;
}

// Gaussian noise along the normals of a finely sampled torus (every vertex
// of valence 6) and of an icosphere (valences 5 and 6) is read back within
// 12 % of its standard deviation, small or large against the triangles.
TEST(NormalNoise, ReadsTheNoisesStandardDeviation)
{
  for (const TriangleMesh& clean : {testing::torusMesh(1.0, 0.4, 192, 96), testing::icosphere(5)}) {
    const double edge = meanEdgeLength(clean);
    for (double sigma : {0.05, 0.2, 0.5}) {
      const std::optional<double> read = normalNoiseAmplitude(addNormalNoise(clean, sigma, 7));
      ASSERT_TRUE(read.has_value());
      EXPECT_NEAR(*read / (sigma * edge), 1.0, 0.12) << "sigma " << sigma << " edges";
    }
  }
}

// The second difference cancels a smooth shape's curvature: a coarse clean
// torus, whose curvature changes from its outside to its hole, reads as
// almost no noise (0.0007 edges), where the offsets from the neighbours'
// centroids themselves spread by 0.02 edges; a sphere reads as none.
TEST(NormalNoise, ASmoothCleanShapeHasAlmostNone)
{
  for (const TriangleMesh& clean : {testing::torusMesh(1.0, 0.6, 48, 24), testing::icosphere(5)}) {
    const std::optional<double> read = normalNoiseAmplitude(clean);
    ASSERT_TRUE(read.has_value());
    EXPECT_LT(*read, 0.005 * meanEdgeLength(clean));
  }
}

// A box's faces are flat and its edges and corners few: the median reads
// the faces, not the creases.
TEST(NormalNoise, CreasesDoNotCountAsNoise)
{
  // The box's 12 triangles, split until its faces have many vertices.
  TriangleMesh cube = testing::box(glm::dvec3(-1.0), glm::dvec3(1.0));
  for (int round = 0; round < 4; ++round) cube = subdivided(cube);
  const std::optional<double> clean = normalNoiseAmplitude(cube);
  ASSERT_TRUE(clean.has_value());
  EXPECT_LT(*clean, 1e-9);
  const std::optional<double> noisy = normalNoiseAmplitude(addNormalNoise(cube, 0.2, 3));
  ASSERT_TRUE(noisy.has_value());
  EXPECT_NEAR(*noisy / (0.2 * meanEdgeLength(cube)), 1.0, 0.2);
}

// In the mesh's units: the same mesh ten thousand times larger reads ten
// thousand times the noise.
TEST(NormalNoise, IsInTheMeshsUnits)
{
  const TriangleMesh noisy = addNormalNoise(testing::icosphere(4), 0.3, 5);
  const std::optional<double> small = normalNoiseAmplitude(noisy);
  const std::optional<double> large = normalNoiseAmplitude(testing::scaled(noisy, 1e4));
  ASSERT_TRUE(small && large);
  EXPECT_NEAR(*large / *small, 1e4, 1e-6 * 1e4);
}

// Vertices on an open mesh's rim have no ring of neighbours and are left
// out, with their neighbours: a flat sheet whose rim curls up (as a scan's
// edge often does) reads as clean, where the rim and its neighbours, more
// than half the vertices, would read as noise; an open sheet's noise is
// read from its inside. A mesh with too few whole rings (a tetrahedron, a
// soup whose corners are all its own) gives no estimate rather than a
// guess.
TEST(NormalNoise, RimsAreLeftOutAndTooFewRingsGiveNone)
{
  const TriangleMesh curled = testing::sheet(16, [](double u, double v) {
    const bool rim = u == 0.0 || u == 1.0 || v == 0.0 || v == 1.0;
    return glm::dvec3(u, v, rim ? 0.03 : 0.0);
  });
  const std::optional<double> clean = normalNoiseAmplitude(curled);
  ASSERT_TRUE(clean.has_value());
  EXPECT_LT(*clean, 0.01 * meanEdgeLength(curled));
  const TriangleMesh sheet = testing::sheet(40, [](double u, double v) { return glm::dvec3(u, v, 0.0); });
  const std::optional<double> read = normalNoiseAmplitude(addNormalNoise(sheet, 0.2, 9));
  ASSERT_TRUE(read.has_value());
  EXPECT_NEAR(*read / (0.2 * meanEdgeLength(sheet)), 1.0, 0.2);

  EXPECT_FALSE(normalNoiseAmplitude(testing::tetrahedron()).has_value());
  const TriangleMesh sphere = testing::icosphere(3);
  TriangleMesh soup;
  for (const glm::uvec3& t : sphere.triangles) {
    const unsigned first = unsigned(soup.positions.size());
    for (int i = 0; i < 3; ++i) soup.positions.push_back(sphere.positions[t[i]]);
    soup.triangles.emplace_back(first, first + 1, first + 2);
  }
  EXPECT_FALSE(normalNoiseAmplitude(soup).has_value());
}

// Only `mostVertices` are read, spread over the mesh: the estimate of a
// large mesh from a sample is the whole's within a few per cent, and a
// sample too small to say anything gives none.
TEST(NormalNoise, ASampleOfTheVerticesReadsAsTheWhole)
{
  const TriangleMesh noisy = addNormalNoise(testing::icosphere(6), 0.3, 11);
  const std::optional<double> whole = normalNoiseAmplitude(noisy, SIZE_MAX);
  const std::optional<double> sample = normalNoiseAmplitude(noisy, 2000);
  ASSERT_TRUE(whole && sample);
  EXPECT_NEAR(*sample / *whole, 1.0, 0.06);
  EXPECT_NE(*sample, *whole) << "a sample, not the whole";
  EXPECT_FALSE(normalNoiseAmplitude(noisy, 20).has_value());
}

// Triangles with a repeated corner (no area) and triangles listed twice
// (their edges then in four triangles, as at a non-manifold seam) change
// the estimate by little: the first are passed over, the second leave
// their vertices out.
TEST(NormalNoise, DegenerateAndRepeatedTrianglesChangeLittle)
{
  const TriangleMesh noisy = addNormalNoise(testing::icosphere(4), 0.3, 13);
  TriangleMesh odd = noisy;
  for (size_t i = 0; i < 40; ++i) {
    const glm::uvec3 t = noisy.triangles[i * 50];
    odd.triangles.emplace_back(t[0], t[0], t[1]);
    odd.triangles.push_back(noisy.triangles[i * 50 + 7]);
  }
  const std::optional<double> clean = normalNoiseAmplitude(noisy), read = normalNoiseAmplitude(odd);
  ASSERT_TRUE(clean && read);
  EXPECT_NEAR(*read / *clean, 1.0, 0.05);
}

}  // namespace
}  // namespace lbmshape
