// Marching cubes on the narrow band gives the grid's mesh: the same
// vertices (position and normal) and the same triangles, in another order.
#include <algorithm>
#include <limits>
#include <map>

#include <omp.h>

#include <gtest/gtest.h>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/surface/band_marching_cubes.hpp"
#include "lbmshape/surface/marching_cubes.hpp"
#include "support/band_fields.hpp"
#include "support/implicit_fields.hpp"

namespace lbmshape {
namespace {

using Corner = std::array<double, 3>;

// Each triangle as its three corner positions, rotated to start at the
// smallest, so meshes that differ only in numbering compare equal.
std::vector<std::array<Corner, 3>> trianglesByPosition(const TriangleMesh& mesh)
{
  std::vector<std::array<Corner, 3>> out;
  for (const auto& t : mesh.triangles) {
    std::array<Corner, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = {mesh.positions[t[k]].x, mesh.positions[t[k]].y, mesh.positions[t[k]].z};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(BandMarchingCubes, GivesTheGridsMesh)
{
  const GridFrame frame = testing::cubicFrame({41, 38, 45}, 0.5, {-10.0, -9.0, -11.0});
  const Volume field = testing::sampleImplicit(frame, [](const glm::dvec3& p) {
    // A torus and a sphere that touch: saddles and thin necks.
    return std::max(testing::torusSdf(p, {0.0, 0.0, 0.0}, 6.0, 2.0), testing::sphereSdf(p, {6.0, 2.0, 3.0}, 3.5));
  });
  const TriangleMesh expected = extractSurface(field, frame);
  auto bricks = testing::bricksNear(field, 3.0);
  const TriangleMesh got = extractSurface(testing::bandOf(field, bricks), frame);

  ASSERT_EQ(got.triangleCount(), expected.triangleCount());
  ASSERT_EQ(got.vertexCount(), expected.vertexCount());
  EXPECT_TRUE(trianglesByPosition(got) == trianglesByPosition(expected));
  // Normals by position.
  std::map<Corner, glm::vec3> normals;
  for (size_t v = 0; v < expected.vertexCount(); ++v)
    normals[{expected.positions[v].x, expected.positions[v].y, expected.positions[v].z}] = expected.normals[v];
  for (size_t v = 0; v < got.vertexCount(); ++v)
    EXPECT_EQ(got.normals[v], (normals[{got.positions[v].x, got.positions[v].y, got.positions[v].z}]))
        << "vertex " << v;
  EXPECT_TRUE(analyzeTopology(got).closedManifold);
  EXPECT_LT(bricks->storedCells(), field.size()) << "a band, not the grid";
}

TEST(BandMarchingCubes, DoesNotDependOnTheThreads)
{
  const GridFrame frame = testing::cubicFrame({33, 33, 33}, 1.0);
  const Volume field = testing::sampleImplicit(frame, [](const glm::dvec3& p) {
    return testing::sphereSdf(p, {16.2, 15.8, 16.1}, 11.3);
  });
  const BandField band = testing::bandOf(field, testing::bricksNear(field, 2.0));
  const TriangleMesh many = extractSurface(band, frame);
  omp_set_num_threads(1);
  const TriangleMesh one = extractSurface(band, frame);
  omp_set_num_threads(omp_get_num_procs());
  EXPECT_EQ(many.positions, one.positions);
  EXPECT_EQ(many.triangles, one.triangles);
}

TEST(BandMarchingCubes, RefusesASampleThatIsNotAFiniteNumber)
{
  const GridFrame frame = testing::cubicFrame({20, 20, 20}, 1.0);
  const Volume field = testing::sampleImplicit(frame, [](const glm::dvec3& p) {
    return testing::sphereSdf(p, {9.6, 10.2, 9.9}, 6.3);
  });
  const BandField band = testing::bandOf(field, testing::bricksNear(field, 2.0));
  ASSERT_NO_THROW(extractSurface(band, frame));
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()})
    for (const size_t at : {size_t(0), band.values().size() / 2, band.values().size() - 1}) {
      BandField broken = band;
      broken.values()[at] = bad;
      EXPECT_THROW(extractSurface(broken, frame), NumericalError) << bad << " at " << at;
    }
}

}  // namespace
}  // namespace lbmshape
