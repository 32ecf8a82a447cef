#include "sdf/grid_frame.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/parameter_names.hpp"

namespace lbmshape {
namespace {

// The longest side of a grid, in cells (cell indices stay well inside int).
constexpr int maxCellsASide = 1 << 16;

void checkBox(const Bounds& box)
{
  const glm::dvec3 s = box.size();
  if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z))
    throw InputError("the mesh's bounding box is not finite");
  if (std::max({s.x, s.y, s.z}) <= 0.0) throw InputError("the mesh's bounding box has zero size");
}

}  // namespace

GridFrame frameWithVoxel(const Bounds& box, double voxel, double marginVoxels)
{
  checkBox(box);
  if (!(voxel > 0.0) || !std::isfinite(voxel)) throw UsageError(nameOf(Parameter::Voxel) + " must be a positive size");
  if (!(marginVoxels >= 0.0)) throw UsageError(nameOf(Parameter::Margin) + " must be zero or more voxels");
  GridFrame frame;
  frame.voxel = voxel;
  const glm::dvec3 size = box.size();
  int cells[3];
  for (int a = 0; a < 3; ++a) {
    // Cell centres span the box plus the margin on both sides.
    double span = size[a] / voxel + 2.0 * marginVoxels;
    double count = std::ceil(span - 1e-9) + 1.0;
    if (count > maxCellsASide) {
      std::ostringstream m;
      m << "a voxel of " << voxel << " makes the grid " << count << " cells long, more than " << maxCellsASide
        << "; use a larger " << nameOf(Parameter::Voxel);
      throw UsageError(m.str());
    }
    cells[a] = int(count);
    frame.origin[a] = box.centre()[a] - 0.5 * (cells[a] - 1) * voxel;
  }
  frame.extent = Extent3{cells[0], cells[1], cells[2]};
  return frame;
}

GridFrame frameWithResolution(const Bounds& box, int resolution, double marginVoxels)
{
  checkBox(box);
  if (!(marginVoxels >= 0.0)) throw UsageError(nameOf(Parameter::Margin) + " must be zero or more voxels");
  if (resolution < 2.0 * marginVoxels + 4.0) {
    std::ostringstream m;
    m << nameOf(Parameter::Resolution) << " " << resolution << " is too coarse for a margin of " << marginVoxels
      << " voxels; use at least " << int(std::ceil(2.0 * marginVoxels + 4.0));
    throw UsageError(m.str());
  }
  if (resolution > maxCellsASide)
    throw UsageError(nameOf(Parameter::Resolution) + " " + std::to_string(resolution) + " is more than " +
                     std::to_string(maxCellsASide) + " cells a side; use a smaller one");
  const glm::dvec3 size = box.size();
  const double longest = std::max({size.x, size.y, size.z});
  // resolution = longest/voxel + 2 margin + 1 cell centres along the longest side
  return frameWithVoxel(box, longest / (resolution - 1.0 - 2.0 * marginVoxels), marginVoxels);
}

}  // namespace lbmshape
