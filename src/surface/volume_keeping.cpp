#include "lbmshape/surface/volume_keeping.hpp"

#include <algorithm>
#include <cmath>

#include "lbmshape/core/ordered_sum.hpp"
#include "lbmshape/surface/field_sampling.hpp"

namespace lbmshape {
namespace {

// V(X + shift) and its derivative, the cells the ramp crosses, over the
// values that `counted(i)` admits.
struct RampSum {
  double voxels = 0.0, slope = 0.0;
};

template <class Counted>
RampSum rampSum(const std::vector<float>& values, double shift, Counted counted)
{
  double voxels = 0.0, slope = 0.0;
#pragma omp parallel for reduction(+ : voxels, slope) schedule(static)
  for (size_t i = 0; i < values.size(); ++i) {
    if (!counted(i)) continue;
    const double x = double(values[i]) + shift + 0.5;
    if (x >= 1.0)
      voxels += 1.0;
    else if (x > 0.0)
      voxels += x, slope += 1.0;
  }
  return {voxels, slope};
}

RampSum rampSum(const Volume& field, double shift)
{
  return rampSum(field.values(), shift, [](size_t) { return true; });
}

RampSum rampSum(const BandField& field, double shift)
{
  const BrickSet& bricks = field.bricks();
  const Extent3& grid = bricks.cells();
  return rampSum(field.values(), shift, [&](size_t i) {
    const glm::ivec3 c = bricks.cell(int32_t(i / brickCells), int(i % brickCells));
    return grid.contains(c.x, c.y, c.z);
  });
}

template <class Field>
double newtonShift(const Field& field, double voxels, double maxShift)
{
  double d = 0.0;
  for (int iteration = 0; iteration < 50; ++iteration) {
    const RampSum s = rampSum(field, d);
    const double missing = voxels - s.voxels;
    if (std::abs(missing) < 1e-9 * std::max(1.0, voxels)) break;
    // No cell on the ramp (a shift past every surface): step by one voxel.
    const double step = s.slope > 0.0 ? missing / s.slope : std::copysign(1.0, missing);
    const double next = std::clamp(d + step, -maxShift, maxShift);
    if (std::abs(next - d) < 1e-7) break;
    d = next;
  }
  return d;
}

}  // namespace

double enclosedVoxels(const Volume& field, double shift) { return rampSum(field, shift).voxels; }
double enclosedVoxels(const BandField& field, double shift) { return rampSum(field, shift).voxels; }

double volumeKeepingShift(const Volume& field, double voxels, double maxShift)
{
  return newtonShift(field, voxels, maxShift);
}

double volumeKeepingShift(const BandField& field, double voxels, double maxShift)
{
  return newtonShift(field, voxels, maxShift);
}

void shiftField(Volume& field, double d)
{
  for (float& x : field.values()) x = float(double(x) + d);
}

void shiftField(BandField& field, double d)
{
  for (float& x : field.values()) x = float(double(x) + d);
}

namespace {

// Below this |grad X| (voxels a voxel) a vertex is taken to move as if
// |grad X| were this: where two fronts meet, a blend's gradient can vanish.
constexpr double leastGradient = 0.25;

template <class Field>
double volumePerShiftOf(const Field& field, const GridFrame& frame, const TriangleMesh& level)
{
  // Per vertex, 1 / |grad X|; then per triangle, a third of its area to each
  // corner (orderedSum: the same sum whatever the number of threads).
  std::vector<double> speed(level.positions.size());
#pragma omp parallel for schedule(static)
  for (size_t v = 0; v < speed.size(); ++v) {
    const glm::dvec3 gradient = sampleWithGradient(field, frame.toGrid(level.positions[v])).second;
    speed[v] = 1.0 / std::max(glm::length(gradient), leastGradient);
  }
  const double perShift = orderedSum<double>(level.triangles.size(), [&](size_t i) {
    const glm::uvec3& t = level.triangles[i];
    const glm::dvec3 &a = level.positions[t.x], &b = level.positions[t.y], &c = level.positions[t.z];
    return 0.5 * glm::length(glm::cross(b - a, c - a)) * (speed[t.x] + speed[t.y] + speed[t.z]) / 3.0;
  });
  return perShift * frame.voxel;
}

}  // namespace

double volumePerShift(const Volume& field, const GridFrame& frame, const TriangleMesh& level)
{
  return volumePerShiftOf(field, frame, level);
}

double volumePerShift(const BandField& field, const GridFrame& frame, const TriangleMesh& level)
{
  return volumePerShiftOf(field, frame, level);
}

double meshVolumeShift(double wanted, double volume, double perShift, double mostRelative)
{
  const double missing = wanted - volume;
  if (!(perShift > 0.0) || !(std::abs(missing) <= mostRelative * std::abs(wanted))) return 0.0;
  return missing / perShift;
}

}  // namespace lbmshape
