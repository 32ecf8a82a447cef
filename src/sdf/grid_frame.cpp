#include "lbmshape/sdf/grid_frame.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/number_text.hpp"
#include "lbmshape/core/parameter_names.hpp"

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

// The fewest voxels the mesh's longest side may span: fewer, and no grid
// resolves its shape (frameWithResolution's least --res, 2 margins + 4).
constexpr double leastVoxelsAcross = 3.0;

}  // namespace

void checkMargin(double marginVoxels, double leastMarginVoxels)
{
  // The largest margin that leaves a grid of at most maxCellsASide cells
  // room for the least mesh; inf or 1e9 would overflow the arithmetic below.
  const double mostMargin = (maxCellsASide - leastVoxelsAcross - 1.0) / 2.0;
  if (!(marginVoxels >= leastMarginVoxels && marginVoxels <= mostMargin))
    throw UsageError(nameOf(Parameter::Margin) + " must be a number of voxels from " + numberText(leastMarginVoxels) +
                     " to " + numberText(mostMargin) + ", not " + numberText(marginVoxels));
}

GridFrame frameWithVoxel(const Bounds& box, double voxel, double marginVoxels)
{
  checkBox(box);
  if (!(voxel > 0.0) || !std::isfinite(voxel)) throw UsageError(nameOf(Parameter::Voxel) + " must be a positive size");
  checkMargin(marginVoxels);
  const glm::dvec3 size = box.size();
  const double longest = std::max({size.x, size.y, size.z});
  if (longest / voxel < leastVoxelsAcross * (1.0 - 1e-12))  // --res at its least gives exactly 3
    throw UsageError(nameOf(Parameter::Voxel) + " " + numberText(voxel) +
                     " is too large for the mesh: its longest side (" + numberText(longest) + ") would span under " +
                     numberText(leastVoxelsAcross) + " voxels; use at most " + numberText(longest / leastVoxelsAcross));
  GridFrame frame;
  frame.voxel = voxel;
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

int leastResolution(double marginVoxels)
{
  checkMargin(marginVoxels);
  // The longest side spans leastVoxelsAcross voxels between the margins:
  // one more cell centre than voxels.
  return int(std::ceil(2.0 * marginVoxels + leastVoxelsAcross + 1.0));
}

void checkResolution(int resolution, double marginVoxels)
{
  const int least = leastResolution(marginVoxels);
  if (resolution < least)
    throw UsageError(nameOf(Parameter::Resolution) + " " + std::to_string(resolution) +
                     " is too coarse for a margin of " + numberText(marginVoxels) + " voxels; use at least " +
                     std::to_string(least));
  if (resolution > maxCellsASide)
    throw UsageError(nameOf(Parameter::Resolution) + " " + std::to_string(resolution) + " is more than " +
                     std::to_string(maxCellsASide) + " cells a side; use a smaller one");
}

GridFrame frameWithResolution(const Bounds& box, int resolution, double marginVoxels)
{
  checkBox(box);
  checkResolution(resolution, marginVoxels);
  const glm::dvec3 size = box.size();
  const double longest = std::max({size.x, size.y, size.z});
  // resolution = longest/voxel + 2 margin + 1 cell centres along the longest side
  return frameWithVoxel(box, longest / (resolution - 1.0 - 2.0 * marginVoxels), marginVoxels);
}

}  // namespace lbmshape
