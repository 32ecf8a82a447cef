// The generated case table and the loop triangulation, checked directly.
#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "lbmshape/surface/cube_cases.hpp"
#include "lbmshape/surface/loop_triangulation.hpp"

namespace lbmshape {
namespace {

bool isCut(int index, const cube::Edge& e) { return ((index >> e.lower) & 1) != ((index >> e.upper) & 1); }

glm::dvec3 corner(int c) { return {cube::cornerOffset(c, 0), cube::cornerOffset(c, 1), cube::cornerOffset(c, 2)}; }

glm::dvec3 midpoint(int edge)
{
  const cube::Edge& e = cube::edges()[edge];
  return 0.5 * (corner(e.lower) + corner(e.upper));
}

TEST(CubeCases, EdgesAndFacesFollowTheDocumentedNumbering)
{
  for (int e = 0; e < 12; ++e) {
    const cube::Edge& edge = cube::edges()[e];
    EXPECT_EQ(edge.axis, e / 4);
    EXPECT_EQ(edge.upper, edge.lower | (1 << edge.axis));
    const glm::dvec3 lower = corner(edge.lower);
    const int first = edge.axis == 0 ? 1 : 0, second = edge.axis == 2 ? 1 : 2;
    EXPECT_EQ(int(lower[first]) | int(lower[second]) << 1, e % 4);
  }
  for (const cube::Face& face : cube::faces()) {
    glm::dvec3 outward(0.0);
    outward[face.axis] = face.side ? 1.0 : -1.0;
    const glm::dvec3 a = corner(face.corners[0]), b = corner(face.corners[1]), c = corner(face.corners[2]);
    EXPECT_GT(glm::dot(glm::cross(b - a, c - b), outward), 0.0) << "face corners must run counter-clockwise";
    for (int c : face.corners) EXPECT_EQ(cube::cornerOffset(c, face.axis), face.side);
  }
}

TEST(CubeCases, EveryCutEdgeIsInExactlyOneLoop)
{
  const auto& cases = cube::cubeCases();
  for (int index = 0; index < 256; ++index) {
    const cube::CubeCase& c = cases[index];
    std::set<int> cut, inLoops;
    for (int e = 0; e < 12; ++e)
      if (isCut(index, cube::edges()[e])) cut.insert(e);
    for (int i = 0; i < c.edgeCount; ++i) EXPECT_TRUE(inLoops.insert(c.edges[i]).second) << "case " << index;
    EXPECT_EQ(cut, inLoops) << "case " << index;
    int total = 0;
    for (int loop = 0; loop < c.loopCount; ++loop) {
      EXPECT_GE(c.loopSize[loop], 3) << "case " << index;
      total += c.loopSize[loop];
    }
    EXPECT_EQ(total, c.edgeCount) << "case " << index;
  }
}

TEST(CubeCases, SingleCornerGivesOneOutwardTriangle)
{
  // Corner 0 inside: the triangle's normal points away from it, to (1, 1, 1).
  const cube::CubeCase& c = cube::cubeCases()[1];
  ASSERT_EQ(c.loopCount, 1);
  ASSERT_EQ(c.loopSize[0], 3);
  const glm::dvec3 a = midpoint(c.edges[0]), b = midpoint(c.edges[1]), d = midpoint(c.edges[2]);
  EXPECT_GT(glm::dot(glm::cross(b - a, d - a), glm::dvec3(1.0)), 0.0);
}

TEST(CubeCases, AmbiguousFacesSeparateTheInsideCorners)
{
  // Corners 0 and 3 (diagonal on the face z = 0) inside: two separate corner triangles.
  const cube::CubeCase& c = cube::cubeCases()[(1 << 0) | (1 << 3)];
  EXPECT_EQ(c.loopCount, 2);
  // Corners 0 and 7 (opposite corners of the cube): two triangles too.
  EXPECT_EQ(cube::cubeCases()[(1 << 0) | (1 << 7)].loopCount, 2);
  // The complement, with the outside corners diagonal, is one loop: a tube
  // around the outside channel from corner 0 to corner 3.
  const cube::CubeCase& tunnel = cube::cubeCases()[255 & ~((1 << 0) | (1 << 3))];
  EXPECT_EQ(tunnel.loopCount, 1);
  EXPECT_EQ(tunnel.loopSize[0], 6);
}

TEST(CubeCases, EveryLoopHasATriangulationWithoutBlockedChords)
{
  const auto& cases = cube::cubeCases();
  std::array<glm::u8vec3, maxLoopSize - 2> triangles;
  for (int index = 0; index < 256; ++index) {
    const cube::CubeCase& c = cases[index];
    int first = 0;
    for (int loop = 0; loop < c.loopCount; ++loop) {
      const int size = c.loopSize[loop];
      std::array<glm::dvec3, 12> points;
      for (int i = 0; i < size; ++i) points[i] = midpoint(c.edges[first + i]);
      ASSERT_EQ(triangulateLoop(points.data(), size, c.blockedChords.data() + first, triangles), size - 2)
          << "case " << index << ", loop " << loop;
      for (int t = 0; t < size - 2; ++t)
        for (int k = 0; k < 3; ++k) {
          const int i = triangles[t][k], j = triangles[t][(k + 1) % 3];
          EXPECT_FALSE((c.blockedChords[first + i] >> j) & 1) << "case " << index;
        }
      first += size;
    }
  }
}

TEST(LoopTriangulation, KeepsTheLoopsWindingAndCoversIt)
{
  // A planar regular hexagon, counter-clockwise around +z.
  std::array<glm::dvec3, 6> hexagon;
  for (int i = 0; i < 6; ++i) {
    const double angle = i * std::numbers::pi / 3;
    hexagon[i] = {std::cos(angle), std::sin(angle), 0.0};
  }
  const std::array<uint16_t, 12> none{};
  std::array<glm::u8vec3, maxLoopSize - 2> triangles;
  ASSERT_EQ(triangulateLoop(hexagon.data(), 6, none.data(), triangles), 4);
  double area = 0;
  for (int t = 0; t < 4; ++t) {
    const glm::dvec3 a = hexagon[triangles[t][0]], b = hexagon[triangles[t][1]], c = hexagon[triangles[t][2]];
    const glm::dvec3 n = glm::cross(b - a, c - a);
    EXPECT_GT(n.z, 0.0);
    area += 0.5 * n.z;
  }
  EXPECT_NEAR(area, 1.5 * std::sqrt(3.0), 1e-12);
}

TEST(LoopTriangulation, AvoidsSliversAndBlockedChords)
{
  // A long thin quad: the short diagonal gives two fair triangles.
  const std::array<glm::dvec3, 4> quad = {glm::dvec3(0, 0, 0), {4, 0, 0}, {4.2, 1, 0}, {0.2, 1, 0}};
  std::array<uint16_t, 12> blocked{};
  std::array<glm::u8vec3, maxLoopSize - 2> triangles;
  ASSERT_EQ(triangulateLoop(quad.data(), 4, blocked.data(), triangles), 2);
  auto usesChord = [&](int i, int j) {
    for (int t = 0; t < 2; ++t)
      for (int k = 0; k < 3; ++k)
        if ((triangles[t][k] == i && triangles[t][(k + 1) % 3] == j) ||
            (triangles[t][k] == j && triangles[t][(k + 1) % 3] == i))
          return true;
    return false;
  };
  EXPECT_TRUE(usesChord(1, 3));  // |13| = 3.8 < |02| = 4.3
  blocked[1] = 1 << 3;
  blocked[3] = 1 << 1;
  ASSERT_EQ(triangulateLoop(quad.data(), 4, blocked.data(), triangles), 2);
  EXPECT_TRUE(usesChord(0, 2));
  blocked[0] = 1 << 2;
  blocked[2] = 1 << 0;
  EXPECT_EQ(triangulateLoop(quad.data(), 4, blocked.data(), triangles), 0);
}

}  // namespace
}  // namespace lbmshape
