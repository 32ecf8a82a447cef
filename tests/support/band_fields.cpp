#include "support/band_fields.hpp"

#include <cmath>
#include <limits>

#include "lbmshape/lbm/band_reference_solver.hpp"
#include "lbmshape/lbm/band_vulkan_solver.hpp"
#include "support/gpu_fixture.hpp"

namespace lbmshape::testing {

std::shared_ptr<BrickSet> bricksNear(const Volume& field, double reach)
{
  auto bricks = std::make_shared<BrickSet>(field.extent());
  const Extent3 grid = bricks->bricks();
  const Extent3& e = field.extent();
  for (int bz = 0; bz < grid.nz; ++bz)
    for (int by = 0; by < grid.ny; ++by)
      for (int bx = 0; bx < grid.nx; ++bx) {
        bool near = false;
        for (int z = 8 * bz; z < std::min(8 * bz + 8, e.nz) && !near; ++z)
          for (int y = 8 * by; y < std::min(8 * by + 8, e.ny) && !near; ++y)
            for (int x = 8 * bx; x < std::min(8 * bx + 8, e.nx) && !near; ++x)
              near = std::abs(field.at(x, y, z)) < reach;
        if (near) bricks->activate(bx, by, bz);
      }
  return bricks;
}

BandField bandOf(const Volume& field, std::shared_ptr<const BrickSet> bricks)
{
  const Extent3& e = field.extent();
  BandField band(bricks, 1000.0f);
  for (size_t s = 0; s < bricks->activeCount(); ++s)
    for (int l = 0; l < brickCells; ++l) {
      const glm::ivec3 c = bricks->cell(int32_t(s), l);
      band.values()[s * brickCells + size_t(l)] = e.contains(c.x, c.y, c.z) ? field.at(c.x, c.y, c.z) : -1000.0f;
    }
  const Extent3 grid = bricks->bricks();
  for (size_t b = 0; b < grid.cells(); ++b) {
    const glm::ivec3 first = 8 * glm::ivec3(int(b % grid.nx), int(b / grid.nx % grid.ny), int(b / grid.nx / grid.ny));
    band.farSides()[b] = field.at(first.x, first.y, first.z) > 0 ? 1 : -1;
  }
  return band;
}

Volume gridOf(const BandField& band)
{
  Volume grid(band.extent(), std::numeric_limits<float>::quiet_NaN());
  const BrickSet& bricks = band.bricks();
  for (size_t s = 0; s < bricks.activeCount(); ++s)
    for (int l = 0; l < brickCells; ++l) {
      const glm::ivec3 c = bricks.cell(int32_t(s), l);
      if (band.extent().contains(c.x, c.y, c.z)) grid.at(c.x, c.y, c.z) = band.values()[s * brickCells + size_t(l)];
    }
  return grid;
}

std::unique_ptr<BandSolver> makeBandSolver(Backend backend, std::shared_ptr<const BrickSet> bricks)
{
  if (backend == Backend::Vulkan) return std::make_unique<BandVulkanSolver>(sharedGpu(), std::move(bricks));
  return std::make_unique<BandReferenceSolver>(std::move(bricks));
}

double maxDifference(const BandField& band, const Volume& grid, const std::function<bool(float gridValue)>& where)
{
  double worst = 0.0;
  const BrickSet& bricks = band.bricks();
  for (size_t s = 0; s < bricks.activeCount(); ++s)
    for (int l = 0; l < brickCells; ++l) {
      const glm::ivec3 c = bricks.cell(int32_t(s), l);
      if (!grid.extent().contains(c.x, c.y, c.z) || !where(grid.at(c.x, c.y, c.z))) continue;
      worst = std::max(worst, double(std::abs(band.values()[s * brickCells + size_t(l)] - grid.at(c.x, c.y, c.z))));
    }
  return worst;
}

BandDifference differenceInside(const BandField& got, const BandField& expected, Extent3 extent)
{
  BandDifference d;
  const BrickSet& bricks = expected.bricks();
  for (size_t i = 0; i < expected.values().size(); ++i) {
    const glm::ivec3 c = bricks.cell(int32_t(i / brickCells), int(i % brickCells));
    if (!extent.contains(c.x, c.y, c.z)) continue;
    d.worst = std::max(d.worst, double(std::abs(got.values()[i] - expected.values()[i])));
    d.scale = std::max(d.scale, double(std::abs(expected.values()[i])));
  }
  return d;
}

}  // namespace lbmshape::testing
