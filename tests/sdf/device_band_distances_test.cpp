// The band's distances on the device (shaders/band_distance.comp) against
// the CPU: every stored cell's against the hierarchy's exact closest point
// (TriangleBvh::closest, double), and the whole signed band against the
// CPU's exact band and propagation; and which of the two a run takes.
#include <cmath>
#include <csignal>
#include <limits>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/pipeline/compute_device.hpp"
#include "lbmshape/sdf/band_signed_distance.hpp"
#include "lbmshape/sdf/cell_space.hpp"
#include "lbmshape/sdf/device_band_distances.hpp"
#include "support/gpu_fixture.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

// Float rounding of the device's walk in grid coordinates (a corner within
// half a float step of its double, some 4e-6 voxel on these grids) and of
// its arithmetic; a walk that missed a triangle, took a wrong region of
// one or a wrong normal is off by far more.
constexpr double kTolerance = 2e-5;

struct DistanceCase {
  std::string name;
  TriangleMesh mesh;
  int resolution;
  double maxVoxels;
};

void PrintTo(const DistanceCase& c, std::ostream* out) { *out << c.name; }

std::vector<DistanceCase> distanceCases()
{
  TriangleMesh holed = testing::icosphere(3);
  holed.triangles.resize(holed.triangles.size() - 40);  // open: the sign from the winding number
  TriangleMesh sliver = testing::box({0.0, 0.0, 0.0}, {1.0, 0.6, 0.4});
  const size_t v = sliver.positions.size();  // and a degenerate triangle inside: counts as its edges
  sliver.positions.push_back({0.2, 0.3, 0.2}), sliver.positions.push_back({0.8, 0.3, 0.2});
  sliver.positions.push_back({0.5, 0.3, 0.2});
  sliver.triangles.push_back({uint32_t(v), uint32_t(v + 1), uint32_t(v + 2)});
  const double unbounded = std::numeric_limits<double>::infinity();
  return {{"sphere", testing::icosphere(4), 48, 8.0},
          {"fine_sphere_coarse_grid", testing::icosphere(5), 20, 8.0},
          {"torus_unbounded", testing::torusMesh(1.0, 0.3, 64, 24), 64, unbounded},
          {"box_off_centre", testing::box({0.1, 0.2, -0.3}, {1.9, 0.8, 0.4}), 56, 5.0},
          {"sphere_with_a_hole", holed, 40, 8.0},
          {"box_with_a_sliver", sliver, 40, 8.0}};
}

class DeviceBandDistances : public testing::GpuTest, public ::testing::WithParamInterface<DistanceCase> {};

TEST_P(DeviceBandDistances, EveryCellHasItsExactDistanceUpToTheBound)
{
  const DistanceCase& c = GetParam();
  const GridFrame frame = frameWithResolution(bounds(c.mesh), c.resolution, 3.0);
  const TriangleBvh tree(c.mesh);
  const auto bricks = bricksNearSurface(c.mesh, tree, frame, 9.0);
  const BandCells cells(*bricks);
  const std::vector<float> device = deviceBandDistances(gpu(), tree, frame, cells, c.maxVoxels);
  ASSERT_EQ(device.size(), cells.count());
  size_t checked = 0, exactCells = 0;
  double worst = 0.0;
  for (size_t i = 0; i < cells.count(); ++i) {
    if (!cells.real(i)) {
      EXPECT_TRUE(std::isinf(device[i])) << "cell " << i << " lies beyond the grid";
      continue;
    }
    const glm::ivec3 cell = cells.coords(i);
    const double exact = tree.closest(frame.cellCentre(cell.x, cell.y, cell.z)).distance / frame.voxel;
    ++checked;
    if (exact > c.maxVoxels + kTolerance) {
      EXPECT_TRUE(std::isinf(device[i])) << "cell " << i << ": " << device[i] << " beyond the bound, exact " << exact;
      continue;
    }
    if (exact < c.maxVoxels - kTolerance) {
      ++exactCells;
      worst = std::max(worst, std::abs(double(device[i]) - exact));
      EXPECT_NEAR(device[i], exact, kTolerance) << "cell " << i << " at " << cell.x << "," << cell.y << "," << cell.z;
    }
  }
  EXPECT_GT(exactCells, checked / 4) << "the case must test distances, not only the bound";
  RecordProperty("worst_difference_voxels", std::to_string(worst));
}

TEST_P(DeviceBandDistances, TheSignedBandIsTheCpusWithEveryDistanceExact)
{
  const DistanceCase& c = GetParam();
  const GridFrame frame = frameWithResolution(bounds(c.mesh), c.resolution, 3.0);
  const bool clamp = std::isfinite(c.maxVoxels);
  const BandDistanceOptions cpuOptions{.halfWidth = 7.0, .clampBeyondHalfWidth = clamp};
  BandDistanceOptions deviceOptions = cpuOptions;
  deviceOptions.distancesFrom = [this](const TriangleBvh&) -> UnsignedBandDistances {
    return [this](const TriangleBvh& tree, const GridFrame& f, const BandCells& cells, double maxVoxels) {
      return deviceBandDistances(gpu(), tree, f, cells, maxVoxels);
    };
  };
  const BandField cpu = signedDistanceBand(c.mesh, frame, cpuOptions);
  const BandField device = signedDistanceBand(c.mesh, frame, deviceOptions);
  ASSERT_EQ(cpu.bricks().activeCount(), device.bricks().activeCount());
  EXPECT_EQ(cpu.farSides(), device.farSides());
  const BandCells cells(device.bricks());
  size_t compared = 0;
  double propagationExcess = 0.0;  // how far beyond the exact distance the CPU's propagation went
  for (size_t i = 0; i < cells.count(); ++i) {
    if (!cells.real(i)) continue;
    const float a = cpu.values()[i], b = device.values()[i];
    if (std::abs(a) > kTolerance) {  // a cell on the surface (a box's face) may have either sign
      ASSERT_EQ(a > 0.0f, b > 0.0f) << "cell " << i << ": the sign differs (" << a << " against " << b << ")";
    }
    // The CPU's exact band reaches 3 voxels; beyond, its propagated
    // distances are some triangle's, never nearer than the nearest.
    if (std::abs(a) <= 3.0f) {
      EXPECT_NEAR(b, a, kTolerance) << "cell " << i;
      ++compared;
    } else {
      EXPECT_LE(std::abs(b), std::abs(a) + kTolerance) << "cell " << i;
      propagationExcess = std::max(propagationExcess, double(std::abs(a) - std::abs(b)));
    }
  }
  EXPECT_GT(compared, 0u);
  RecordProperty("cpu_propagation_excess_voxels", std::to_string(propagationExcess));
}

INSTANTIATE_TEST_SUITE_P(Shapes, DeviceBandDistances, ::testing::ValuesIn(distanceCases()),
                         [](const auto& info) { return info.param.name; });

TEST(DeviceBandDistancesInterrupted, AStopRequestedBeforehandEndsItWithNothingWritten)
{
  GTEST_FLAG_SET(death_test_style, "threadsafe");  // the child opens its own device
  EXPECT_EXIT(
      {
        const TriangleMesh mesh = testing::icosphere(3);
        const GridFrame frame = frameWithResolution(bounds(mesh), 32, 3.0);
        const TriangleBvh tree(mesh);
        const auto bricks = bricksNearSurface(mesh, tree, frame, 9.0);
        const BandCells cells(*bricks);
        interrupt::installHandler();
        std::raise(SIGINT);  // the request: the process goes on
        try {
          deviceBandDistances(testing::sharedGpu(), tree, frame, cells, 8.0);
        } catch (const Interrupted&) {
          std::_Exit(0);
        }
        std::_Exit(1);
      },
      ::testing::ExitedWithCode(0), "");
}

// Which one a run takes: ComputeDevice::bandDistances.
TEST(DistancesOnTheDevice, AutoTakesTheCpuOnACpuDeviceAndEitherWhenForced)
{
  const TriangleMesh mesh = testing::icosphere(2);
  const TriangleBvh tree(mesh);
  const ComputeDevice automatic("", false), cpu("", false, RunsOn::Cpu), device("", false, RunsOn::Device);
  const bool gpuChosen = automatic.gpu()->description().type != "cpu";
  EXPECT_EQ(automatic.distancesOnTheDevice(tree), gpuChosen);
  EXPECT_FALSE(cpu.distancesOnTheDevice(tree));
  EXPECT_FALSE(bool(cpu.bandDistances(tree)));
  EXPECT_TRUE(device.distancesOnTheDevice(tree));
  EXPECT_TRUE(bool(device.bandDistances(tree)));
  EXPECT_FALSE(ComputeDevice("reference", false).distancesOnTheDevice(tree));
  EXPECT_THROW(ComputeDevice("reference", false, RunsOn::Device).distancesOnTheDevice(tree), UsageError);
}

TEST(DeviceHoldsTree, CountsTheNodesAndTheTrianglesAgainstOneBinding)
{
  const TriangleMesh mesh = testing::icosphere(2);  // 320 triangles: 20 KB of them
  const TriangleBvh tree(mesh);
  EXPECT_TRUE(deviceHoldsTree(uint64_t(1) << 20, tree));
  EXPECT_FALSE(deviceHoldsTree(uint64_t(16) << 10, tree));
}

}  // namespace
}  // namespace lbmshape
