// Where a grid sits in the world: cell (i, j, k) has its centre at
// origin + voxel * (i, j, k). Fields on the grid (the signed distance X) are
// measured in voxels, so gamma is in voxels^2 per step whatever the mesh's units.
#pragma once

#include <glm/glm.hpp>

#include "lbmshape/core/extent.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

struct GridFrame {
  glm::dvec3 origin{0.0};  // world position of the centre of cell (0, 0, 0)
  double voxel = 1.0;      // edge of a cubic voxel, in world units
  Extent3 extent;

  glm::dvec3 toWorld(const glm::dvec3& grid) const { return origin + voxel * grid; }
  glm::dvec3 toGrid(const glm::dvec3& world) const { return (world - origin) / voxel; }
  glm::dvec3 cellCentre(int x, int y, int z) const { return toWorld(glm::dvec3(x, y, z)); }
};

// A grid covering `box` plus `marginVoxels` on every side, with `resolution`
// cells along the longest side (margins included) and cubic voxels; the box is
// centred in the grid. Throws UsageError for a resolution too small for the
// margin, and InputError for an empty or non-finite box.
GridFrame frameWithResolution(const Bounds& box, int resolution, double marginVoxels);

// UsageError naming --margin unless `marginVoxels` is from the least given
// to the most a grid of 65536 cells a side has room for.
void checkMargin(double marginVoxels, double leastMarginVoxels = 0.0);

// The least resolution frameWithResolution accepts with this margin.
int leastResolution(double marginVoxels);
// UsageError naming --res unless `resolution` is from leastResolution() to
// the most cells a side (65536); and checkMargin()'s.
void checkResolution(int resolution, double marginVoxels);

// The same with a given voxel size (world units) instead of a resolution.
GridFrame frameWithVoxel(const Bounds& box, double voxel, double marginVoxels);

}  // namespace lbmshape
