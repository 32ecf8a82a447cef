// --radius: a smoothing strength in the mesh's own units, the same whatever
// the grid. Diffusion for a time t smooths with a Gaussian kernel of
// variance 2 gamma t, so a radius R (the kernel's standard deviation) is
// (R / voxel)^2 voxels^2 of variance, which the lattice reaches in a number
// of steps that grows with the square of the resolution. A run of n steps
// from equilibrium spreads a pulse a little less than 2 gamma n at first
// (feature_probe.hpp's spreadVariance): the steps are the fewest that reach
// the variance, counting that.
#pragma once

#include <optional>

#include "lbmshape/sdf/grid_frame.hpp"

namespace lbmshape {

struct Bounds;
struct GridOptions;

// Throws UsageError, naming --radius, unless it is absent or a positive
// finite length, and when --steps is given too.
void checkRadius(std::optional<double> radius, bool stepsGiven);

// The fewest lattice steps at `gamma` whose spread reaches radiusVoxels^2,
// at least 1. Throws UsageError, naming --radius, when that is beyond
// parameter_bounds::maxSteps.
int stepsForRadius(double radiusVoxels, double gamma);

// The grid's margin, in voxels, for smoothing of `radius` (the mesh's
// units) around a mesh whose longest side is `longestSide`, on a grid of
// `resolution` cells along it or, given, of voxels of size `voxel`.
// Smoothing lifts the field outside the surface by about as far as it
// diffuses; where the margin is thinner than that, the field crosses zero
// at the grid's walls (a unit sphere smoothed with a radius of 1.7 margins
// came out open there). Two radii hold it. With a resolution a wider margin
// makes the voxels larger, voxel = longestSide / (resolution - 1 - 2 m),
// so m >= 2 radius / voxel is solved for m; UsageError, naming --radius,
// where that leaves the mesh too few cells of the resolution.
double marginForRadius(double radius, double longestSide, int resolution, std::optional<double> voxel);

// The grid around `box` for smoothing of `radius`: `grid`'s margin widened
// to marginForRadius where it is less, and the grid placed with it
// (placeGrid). A grid that cannot be made, or that has more cells than the
// distance stages number (2^32, sdf/signed_distance.cpp), is a UsageError
// that names --radius, which the user gave, not only the margin or the
// grid, which they did not.
GridFrame gridForRadius(double radius, const Bounds& box, GridOptions& grid);

}  // namespace lbmshape
