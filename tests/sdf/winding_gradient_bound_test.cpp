// The gradient bound that lets the sign stage skip winding-number
// evaluations: which edges it keeps, and that it really bounds |grad w|.
#include <gtest/gtest.h>

#include <random>

#include "lbmshape/sdf/triangle_bvh.hpp"
#include "lbmshape/sdf/winding_gradient_bound.hpp"
#include "support/test_meshes.hpp"

#include "sdf_fixtures.hpp"

namespace lbmshape {
namespace {

// Every triangle with its own three vertices, as STL files store them.
TriangleMesh unwelded(const TriangleMesh& mesh)
{
  TriangleMesh soup;
  for (const auto& t : mesh.triangles) {
    const uint32_t v = uint32_t(soup.positions.size());
    for (int k = 0; k < 3; ++k) soup.positions.push_back(mesh.positions[t[k]]);
    soup.triangles.push_back({v, v + 1, v + 2});
  }
  return soup;
}

TEST(WindingGradientBound, ClosedMeshesHaveNoOpenEdges)
{
  const TriangleMesh sphere = testing::icosphere(2, 1.0);
  EXPECT_EQ(WindingGradientBound(sphere).openEdgeCount(), 0u);
  EXPECT_EQ(WindingGradientBound(unwelded(sphere)).openEdgeCount(), 0u);
  // Two closed spheres crossing each other: still no boundary.
  const WindingGradientBound two(testing::merged(sphere, testing::icosphere(2, 0.5, {0.9, 0, 0})));
  EXPECT_EQ(two.openEdgeCount(), 0u);
  EXPECT_EQ(two.over({-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}, 1e9), 0.0);
}

TEST(WindingGradientBound, KeepsHoleRimsAndMisorientedEdges)
{
  TriangleMesh sphere = testing::icosphere(2, 1.0);
  EXPECT_EQ(WindingGradientBound(testing::sdf::withHoles(sphere, 1, 1)).openEdgeCount(), 3u);
  // A flipped triangle: each of its edges now runs the same way as its
  // neighbour's, so both copies remain.
  std::swap(sphere.triangles[7].y, sphere.triangles[7].z);
  EXPECT_EQ(WindingGradientBound(sphere).openEdgeCount(), 6u);
}

TEST(WindingGradientBound, BoundsTheGradientOfTheExactWindingNumber)
{
  const TriangleMesh mesh = testing::sdf::withHoles(testing::icosphere(3, 1.0), 12, 2);
  const TriangleBvh bvh(mesh);
  const WindingGradientBound bound(mesh);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.4, 1.4);
  int tested = 0;
  for (int k = 0; k < 400; ++k) {
    const glm::dvec3 centre(u(rng), u(rng), u(rng));
    const glm::dvec3 half(0.05);
    const double g = bound.over(centre - half, centre + half, 1e30);
    if (std::isinf(g)) continue;                       // a rim edge meets the box
    if (bvh.closest(centre).distance < 0.1) continue;  // the box may cross the surface, where w jumps
    // Central differences at a few points of the box.
    for (int s = 0; s < 4; ++s) {
      const glm::dvec3 p = centre + 0.05 * glm::dvec3(u(rng), u(rng), u(rng)) / 1.4;
      const double h = 1e-4;
      glm::dvec3 gradient;
      for (int a = 0; a < 3; ++a) {
        glm::dvec3 e(0.0);
        e[a] = h;
        gradient[a] = (bvh.exactWindingNumber(p + e) - bvh.exactWindingNumber(p - e)) / (2 * h);
      }
      EXPECT_LE(glm::length(gradient), g * 1.0001 + 1e-6);
      ++tested;
    }
  }
  EXPECT_GT(tested, 100);
}

}  // namespace
}  // namespace lbmshape
