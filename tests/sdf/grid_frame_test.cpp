// Where the grid goes around a mesh (--res, --voxel, --margin): cubic voxels,
// the requested count along the longest side, at least the margin on every
// side, and the box in the middle, whatever the mesh's position and units.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/number_text.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "lbmshape/sdf/grid_frame.hpp"

namespace lbmshape {
namespace {

// Off the origin, not a round size, and a different length on every axis;
// the longest side is y.
const Bounds kBox{{1000.25, -50.5, 3.0}, {1002.0, -46.75, 4.125}};
constexpr double kMargin = 4.0;

int cells(const GridFrame& f, int axis) { return axis == 0 ? f.extent.nx : axis == 1 ? f.extent.ny : f.extent.nz; }

// Empty voxels between the box and the outermost cell centres, low and high side.
double lowMargin(const GridFrame& f, int axis) { return (kBox.min[axis] - f.origin[axis]) / f.voxel; }
double highMargin(const GridFrame& f, int axis)
{
  return (f.origin[axis] + (cells(f, axis) - 1) * f.voxel - kBox.max[axis]) / f.voxel;
}

TEST(GridFrame, ResolutionIsTheCellCountAlongTheLongestSide)
{
  for (int resolution : {16, 48, 129}) {
    const GridFrame f = frameWithResolution(kBox, resolution, kMargin);
    EXPECT_EQ(f.extent.ny, resolution);
    EXPECT_LT(f.extent.nx, resolution);
    EXPECT_LT(f.extent.nz, resolution);
    // One voxel size serves all three axes: the longest side spans
    // resolution - 1 cell centres, margins included.
    EXPECT_NEAR(f.voxel, kBox.size().y / (resolution - 1 - 2 * kMargin), 1e-12 * f.voxel);
    // Along the longest side the margin is exact; along the others the cell
    // count is rounded up, so it is at least the margin and under one more.
    EXPECT_NEAR(lowMargin(f, 1), kMargin, 1e-9);
    EXPECT_NEAR(highMargin(f, 1), kMargin, 1e-9);
    for (int axis : {0, 2}) {
      EXPECT_GE(lowMargin(f, axis), kMargin - 1e-9) << "axis " << axis;
      EXPECT_LT(lowMargin(f, axis), kMargin + 0.5 + 1e-9) << "axis " << axis;
      EXPECT_NEAR(lowMargin(f, axis), highMargin(f, axis), 1e-9) << "the box is centred; axis " << axis;
    }
  }
}

TEST(GridFrame, VoxelIsTheVoxel)
{
  for (double voxel : {0.05, 0.125, 0.3}) {
    const GridFrame f = frameWithVoxel(kBox, voxel, kMargin);
    EXPECT_EQ(f.voxel, voxel);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_GE(lowMargin(f, axis), kMargin - 1e-9) << "voxel " << voxel << ", axis " << axis;
      EXPECT_LT(lowMargin(f, axis), kMargin + 0.5 + 1e-9) << "voxel " << voxel << ", axis " << axis;
      EXPECT_NEAR(lowMargin(f, axis), highMargin(f, axis), 1e-9) << "voxel " << voxel << ", axis " << axis;
    }
  }
}

TEST(GridFrame, CellCentresMapToTheWorldAndBack)
{
  const GridFrame f = frameWithResolution(kBox, 40, kMargin);
  EXPECT_EQ(f.cellCentre(0, 0, 0), f.origin);
  const glm::dvec3 p(1001.1, -48.2, 3.7);
  const glm::dvec3 back = f.toWorld(f.toGrid(p));
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(back[axis], p[axis], 1e-9);
  EXPECT_NEAR(glm::length(f.cellCentre(1, 1, 1) - f.origin), std::sqrt(3.0) * f.voxel, 1e-9);
}

TEST(GridFrame, PlaceGridFollowsTheOptions)
{
  GridOptions options;
  options.resolution = 32;
  options.marginVoxels = 2.0;
  EXPECT_EQ(placeGrid(kBox, options).extent.ny, 32);
  options.voxel = 0.2;
  const GridFrame byVoxel = placeGrid(kBox, options);
  EXPECT_EQ(byVoxel.voxel, 0.2) << "--voxel wins over the default --res";
  EXPECT_NEAR(lowMargin(byVoxel, 1), 2.0, 0.5 + 1e-9);
}

TEST(GridFrame, RejectsWhatCannotBeAGrid)
{
  EXPECT_THROW(frameWithResolution(kBox, 10, kMargin), UsageError) << "no room inside a margin of 4 on both sides";
  EXPECT_THROW(frameWithVoxel(kBox, 0.0, kMargin), UsageError);
  EXPECT_THROW(frameWithVoxel(kBox, 1e-6, kMargin), UsageError) << "millions of cells along a side";
  EXPECT_THROW(frameWithVoxel(Bounds{{1, 1, 1}, {1, 1, 1}}, 0.1, kMargin), InputError) << "a point has no size";
}

// Too many cells a side is the option's fault, and the message says which
// way to change it: a smaller resolution, a larger voxel.
TEST(GridFrame, TooLongAGridNamesTheWayBack)
{
  try {
    frameWithResolution(kBox, 100000, kMargin);
    FAIL() << "a grid of 100000 cells a side";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(nameOf(Parameter::Resolution) + " 100000"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("smaller"), std::string::npos) << e.what();
  }
  try {
    frameWithVoxel(kBox, 1e-6, kMargin);
    FAIL() << "millions of cells a side";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("larger " + nameOf(Parameter::Voxel)), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find(nameOf(Parameter::Resolution)), std::string::npos)
        << "a larger --res would be longer still";
  }
  EXPECT_NO_THROW(frameWithResolution(kBox, 1 << 16, kMargin));
}

// A voxel larger than a third of the mesh is --res below its least: the
// grid would hold the mesh in a voxel or two (1e300 made a grid whose far
// corner overflowed single precision, and a mesh of NaNs).
TEST(GridFrame, AVoxelLargerThanTheMeshSaysWhatFits)
{
  const double longest = kBox.size().y;
  for (const double voxel : {1e300, 2.0 * longest, 0.34 * longest}) {
    try {
      frameWithVoxel(kBox, voxel, kMargin);
      FAIL() << "a voxel of " << voxel << " around a mesh " << longest << " long";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(nameOf(Parameter::Voxel) + " " + numberText(voxel)), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("at most " + numberText(longest / 3.0)), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(frameWithVoxel(kBox, longest / 3.0, kMargin));
  // The least --res is exactly that voxel.
  EXPECT_NO_THROW(frameWithResolution(kBox, leastResolution(kMargin), kMargin));
  EXPECT_EQ(leastResolution(kMargin), 12);
}

// A margin is a number of voxels a grid has room for: inf and 1e9 made the
// least --res overflow an int ("use at least -2147483648").
TEST(GridFrame, TheMarginIsBoundedByTheLongestGrid)
{
  for (const double margin : {-1.0, 1e9, std::numeric_limits<double>::infinity(), std::nan("")}) {
    try {
      frameWithResolution(kBox, 128, margin);
      FAIL() << "a margin of " << margin;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(nameOf(Parameter::Margin) + " must be a number of voxels from 0 to 32766"),
                std::string::npos)
          << e.what();
    }
    EXPECT_THROW(frameWithVoxel(kBox, 0.1, margin), UsageError) << margin;
  }
  EXPECT_NO_THROW(frameWithResolution(kBox, 65536, 32766.0));
}

}  // namespace
}  // namespace lbmshape
