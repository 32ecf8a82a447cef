#include "lbmshape/pipeline/smoothing_radius.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_bounds.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "lbmshape/pipeline/feature_probe.hpp"

namespace lbmshape {
namespace {

std::string number(double x)
{
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

void checkRadius(std::optional<double> radius, bool stepsGiven)
{
  if (!radius) return;
  if (!(std::isfinite(*radius) && *radius > 0.0))
    throw UsageError(nameOf(Parameter::Radius) + " must be a positive length in the mesh's units, not " +
                     number(*radius));
  if (stepsGiven)
    throw UsageError(nameOf(Parameter::Radius) + " and " + nameOf(Parameter::Steps) +
                     " both say how much to smooth: give one");
}

int stepsForRadius(double radiusVoxels, double gamma)
{
  const double variance = radiusVoxels * radiusVoxels;
  // The spread grows with the steps and differs from 2 gamma n by a bounded
  // start-up term (at most a few steps' worth, either way): the answer is
  // found by walking from there.
  const double plain = std::ceil(variance / (2.0 * gamma));
  if (!(plain <= double(parameter_bounds::maxSteps)))
    throw UsageError(nameOf(Parameter::Radius) + " of " + number(radiusVoxels) + " voxels needs more than " +
                     std::to_string(parameter_bounds::maxSteps) +
                     " steps at this grid; give a smaller radius or a coarser grid");
  int steps = std::max(1, int(plain));
  while (steps > 1 && spreadVariance(gamma, steps - 1) >= variance) --steps;
  while (spreadVariance(gamma, steps) < variance) ++steps;
  return steps;
}

double marginForRadius(double radius, double longestSide, int resolution, std::optional<double> voxel)
{
  if (voxel) return std::ceil(2.0 * radius / *voxel);
  const double margin = std::ceil(2.0 * radius * (resolution - 1.0) / (longestSide + 4.0 * radius));
  if (resolution < 2.0 * margin + 4.0)
    throw UsageError(nameOf(Parameter::Radius) + " " + number(radius) + " is too large for " +
                     nameOf(Parameter::Resolution) + " " + std::to_string(resolution) +
                     ": a margin of two radii each side of the mesh (longest side " + number(longestSide) +
                     ") would take " + number(margin) +
                     " of its cells each side, leaving the mesh too few; give a "
                     "smaller radius or a finer grid");
  return margin;
}

GridFrame gridForRadius(double radius, const Bounds& box, GridOptions& grid)
{
  const glm::dvec3 size = box.size();
  grid.marginVoxels = std::max(
      grid.marginVoxels, marginForRadius(radius, std::max({size.x, size.y, size.z}), grid.resolution, grid.voxel));
  const std::string widened =
      nameOf(Parameter::Radius) + " " + number(radius) + " widens the grid's margin to two radii";
  GridFrame frame;
  try {
    frame = placeGrid(box, grid);
  } catch (const UsageError& e) {
    throw UsageError(widened + ": " + e.what());
  }
  if (frame.extent.cells() >= std::numeric_limits<uint32_t>::max())
    throw UsageError(widened + ", which makes the grid " + frame.extent.toString() +
                     ", more than 4e9 cells; give a smaller radius or a larger " + nameOf(Parameter::Voxel));
  return frame;
}

}  // namespace lbmshape
