// Where meshes, labels and the legend go, and the camera that frames them.
#include <gtest/gtest.h>

#include "lbmshape/render/layout.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape::render {
namespace {

Picture pictureOf(const std::vector<TriangleMesh>& meshes, int width, int height, bool labels, bool legend)
{
  Picture p;
  p.width = width, p.height = height, p.labels = labels;
  for (const TriangleMesh& m : meshes) p.panels.push_back({&m, {}, "x"});
  if (legend) p.legend = Legend{"t", 0, 1, false};
  return p;
}

TEST(Layout, OneRowUpToFourThenAboutTwiceAsWideAsHigh)
{
  EXPECT_EQ(columnsFor(1), 1);
  EXPECT_EQ(columnsFor(4), 4);
  EXPECT_EQ(columnsFor(8), 4);
  EXPECT_EQ(columnsFor(48), 10);
  EXPECT_EQ(columnsFor(6, 6), 6);
  EXPECT_EQ(columnsFor(3, 6), 3) << "never more columns than meshes";
}

TEST(Layout, CellsTileThePictureWithoutOverlapAboveTheLegend)
{
  const std::vector<TriangleMesh> meshes(7, testing::icosphere(1));
  for (bool labels : {false, true})
    for (bool legend : {false, true}) {
      const Picture p = pictureOf(meshes, 1000, 700, labels, legend);
      const Layout l = arrange(p);
      ASSERT_EQ(l.meshCells.size(), 7u);
      EXPECT_EQ(l.labelCells.size(), labels ? 7u : 0u);
      EXPECT_EQ(l.legend.has_value(), legend);
      const int bottom = legend ? l.legend->y : p.height;
      std::vector<Rect> all = l.meshCells;
      all.insert(all.end(), l.labelCells.begin(), l.labelCells.end());
      for (size_t i = 0; i < all.size(); ++i) {
        EXPECT_GE(all[i].x, 0);
        EXPECT_GE(all[i].y, 0);
        EXPECT_GT(all[i].width, 0);
        EXPECT_GT(all[i].height, 0);
        EXPECT_LE(all[i].x + all[i].width, p.width);
        EXPECT_LE(all[i].y + all[i].height, bottom);
        for (size_t j = 0; j < i; ++j) {
          const bool apart = all[i].x + all[i].width <= all[j].x || all[j].x + all[j].width <= all[i].x ||
                             all[i].y + all[i].height <= all[j].y || all[j].y + all[j].height <= all[i].y;
          EXPECT_TRUE(apart) << i << " overlaps " << j;
        }
      }
    }
}

TEST(Layout, TheDefaultSizeGivesEachMeshASquareCell)
{
  EXPECT_EQ(defaultPictureSize(1, false, false), glm::ivec2(512, 512));
  EXPECT_EQ(defaultPictureSize(2, false, false), glm::ivec2(1024, 512));
  EXPECT_EQ(defaultPictureSize(8, false, false), glm::ivec2(4 * 384, 2 * 384));
  // Many meshes get smaller cells, within the bounds of --size.
  const glm::ivec2 many = defaultPictureSize(256, true, true);
  EXPECT_LE(many.x, 8192);
  EXPECT_LE(many.y, 8192);
  EXPECT_LE(long(many.x) * many.y, 4096L * 4096L);
  EXPECT_GE(many.x / columnsFor(256), 64);
  const glm::ivec2 labelled = defaultPictureSize(2, true, true);
  EXPECT_EQ(labelled.x, 1024);
  EXPECT_GT(labelled.y, 512);
}

TEST(Framing, EveryMeshFitsItsCellAtOneScale)
{
  // Two boxes far apart: the camera frames their union, so both fit and
  // a unit is the same number of pixels in each cell.
  const std::vector<TriangleMesh> meshes = {testing::box({0, 0, 0}, {1, 2, 3}), testing::box({10, -5, 2}, {11, -4, 9})};
  for (const char* view : {"front", "side", "top", "iso", "30,-60"}) {
    Picture p = pictureOf(meshes, 800, 400, false, false);
    p.view = parseView(view);
    const Layout l = arrange(p);
    const Framing f = frame(p, l.meshCells[0]);
    double widest = 0.0;
    for (const TriangleMesh& m : meshes)
      for (const glm::dvec3& q : m.positions) {
        const glm::vec4 clip = f.clipFromCentred * glm::vec4(glm::vec3((q - f.centre) / f.unit), 1.0f);
        EXPECT_LE(std::abs(clip.x), 0.921f) << view;
        EXPECT_LE(std::abs(clip.y), 0.921f) << view;
        EXPECT_GE(clip.z, 0.0f) << view;
        EXPECT_LE(clip.z, 1.0f) << view;
        EXPECT_FLOAT_EQ(clip.w, 1.0f);
        widest = std::max(widest, double(std::max(std::abs(clip.x), std::abs(clip.y))));
      }
    EXPECT_GT(widest, 0.5) << view;
  }
}

TEST(Framing, TheBoxFillsNinetyTwoPercentOfTheTighterDirection)
{
  // One box: its corners are vertices, so the widest one lands on the margin.
  const std::vector<TriangleMesh> meshes = {testing::box({0, 0, 0}, {1, 2, 3})};
  for (const char* view : {"front", "side", "top", "iso", "30,-60"}) {
    Picture p = pictureOf(meshes, 300, 500, false, false);
    p.view = parseView(view);
    const Framing f = frame(p, arrange(p).meshCells[0]);
    double widest = 0.0;
    for (const glm::dvec3& q : meshes[0].positions) {
      const glm::vec4 clip = f.clipFromCentred * glm::vec4(glm::vec3((q - f.centre) / f.unit), 1.0f);
      widest = std::max(widest, double(std::max(std::abs(clip.x), std::abs(clip.y))));
    }
    EXPECT_NEAR(widest, 0.92, 1e-5) << view;
  }
}

TEST(Framing, NearerPointsHaveSmallerDepth)
{
  const std::vector<TriangleMesh> meshes = {testing::box({-1, -1, -1}, {1, 1, 1})};
  Picture p = pictureOf(meshes, 256, 256, false, false);
  const Framing f = frame(p, arrange(p).meshCells[0]);
  const float nearZ = (f.clipFromCentred * glm::vec4(0, 0, 1, 1)).z,
              farZ = (f.clipFromCentred * glm::vec4(0, 0, -1, 1)).z;
  EXPECT_LT(nearZ, farZ);
}

}  // namespace
}  // namespace lbmshape::render
