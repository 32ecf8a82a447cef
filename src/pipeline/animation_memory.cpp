#include "lbmshape/pipeline/animation_memory.hpp"

#include <algorithm>
#include <cmath>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/host_memory.hpp"
#include "lbmshape/core/memory_sizes.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"

namespace lbmshape {
namespace {

// The shapes in between may have more area than either end.
constexpr double areaMargin = 1.5;

}  // namespace

double animationBytes(double areaInVoxels, int frames)
{
  return areaMargin * areaInVoxels * trianglesPerVoxelArea * animationBytesPerTriangle * double(frames);
}

void checkAnimationFileFits(const TriangleMesh& source, const TriangleMesh& target, double voxel, int frames)
{
  const double sourceArea = surfaceArea(source) / (voxel * voxel), targetArea = surfaceArea(target) / (voxel * voxel);
  // The smaller surface, and a fifth off: refused only where it surely
  // would not fit (frames in between may be smaller, or empty).
  const double perFrame = 0.8 * std::min(sourceArea, targetArea) * trianglesPerVoxelArea * glbBytesPerTriangle;
  const double limit = double(UINT32_MAX);
  if (perFrame * frames <= limit) return;
  // The frames that surely fit: the larger surface, in full.
  const double largest = std::max(sourceArea, targetArea);
  const int fit = int(std::floor(limit / (largest * trianglesPerVoxelArea * glbBytesPerTriangle)));
  throw OutputError("morph.glb's " + std::to_string(frames) + " frames would take about " +
                    mebibytes(uint64_t(perFrame * frames)) + ", past the 4 GiB a .glb holds; about " +
                    std::to_string(fit) + " frames would fit, or a coarser " + nameOf(Parameter::Resolution) + ", " +
                    nameOf(Parameter::Compression) + " (about five times smaller) or " + nameOf(Parameter::Animation));
}

void checkAnimationFits(const TriangleMesh& source, const TriangleMesh& target, double voxel, int frames,
                        FramesHeldBy heldBy)
{
  const double area = std::max(surfaceArea(source), surfaceArea(target)) / (voxel * voxel);
  const double needed = animationBytes(area, frames);
  const double allowed = double(hostMemoryBytes());
  if (needed <= allowed) return;
  const int fit = int(std::floor(allowed / animationBytes(area, 1) * 0.95));
  const bool preview = heldBy == FramesHeldBy::Preview;
  throw DeviceError(
      "the " + std::to_string(frames) + " frames of " + (preview ? "the preview" : "a compressed morph.glb") +
      " need about " + mebibytes(uint64_t(needed)) + " but this machine allows " + mebibytes(uint64_t(allowed)) + "; " +
      (fit >= 2 ? "about " + std::to_string(fit) + " frames would fit" : "not even 2 frames would fit") +
      (preview ? ", or leave out " + nameOf(Parameter::Preview)
               : ", or leave out " + nameOf(Parameter::Compression) +
                     " (a plain morph.glb is written as the frames come) or give " + nameOf(Parameter::Animation)));
}

}  // namespace lbmshape
