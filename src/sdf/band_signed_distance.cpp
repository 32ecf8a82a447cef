#include "lbmshape/sdf/band_signed_distance.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/stopwatch.hpp"
#include "lbmshape/sdf/band_distance.hpp"
#include "lbmshape/sdf/cell_space.hpp"
#include "lbmshape/sdf/far_field.hpp"
#include "lbmshape/sdf/hole_radius.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"
#include "lbmshape/sdf/winding_gradient_bound.hpp"
#include "lbmshape/sdf/winding_sign.hpp"

namespace lbmshape {
namespace {

// The fans over an open mesh's holes (hole_radius.hpp), where the surface
// that closes them lies: the band reaches there as it reaches the
// triangles, and a bit further by how far the rims leave their planes.
// Without them the band stopped at the triangles and cut that surface off
// over every hole wider than itself; it was then widened everywhere, over
// the whole mesh, to the widest hole's radius (the open bunny scan at 384:
// 73 voxels, 72,159 bricks, 1.7 GB, 47 s).
struct FanReach {
  std::optional<TriangleBvh> tree;  // none for a closed mesh
  double beyond = 0.0;              // in the mesh's units, beyond the band's reach
};

FanReach fanReach(const TriangleMesh& mesh, const TriangleBvh& tree, const GridFrame& frame, double halfWidth)
{
  // A planar film of less area than a disk of radius halfWidth has no
  // point farther than that from its rim: the band holds it without a fan.
  // (Three quarters of it, for the band's own rounding.) A rim far from
  // planar (a slit around a sphere's equator: its two edges' areas cancel)
  // may have a film larger than its fan's area; where that film leaves the
  // band, the band is widened (pipeline/denoise.cpp).
  const double leastRadius = 0.75 * std::max(halfWidth, 1.0) * frame.voxel;
  ClosingFans fans = closingFans(mesh, std::acos(-1.0) * leastRadius * leastRadius,
                                 [&tree](const glm::dvec3& p) { return tree.windingNumber(p); });
  FanReach reach;
  if (fans.mesh.triangles.empty()) return reach;
  reach.tree.emplace(fans.mesh, TriangleBvh::Queries::ClosestOnly);
  reach.beyond = fans.farthestOffPlane;
  return reach;
}

// The bricks with a cell within `reachVoxels` of the surface (or of the fans
// over its holes), activated in brick order (so slots do not depend on the
// threads). A brick passes when the surface comes within reach of one of
// its eight 4 x 4 x 4 quarters, each tested from its centre: the test is
// conservative (no brick with a cell in reach is missed) and overshoots by
// at most a quarter's half diagonal, 2.6 voxels, where testing whole bricks
// would overshoot by 6.1.
std::shared_ptr<BrickSet> bandBricks(const TriangleBvh& bvh, const FanReach& fans, const GridFrame& frame,
                                     double reachVoxels)
{
  auto bricks = std::make_shared<BrickSet>(frame.extent);
  const Extent3 grid = bricks->bricks();
  auto reachFrom = [&](int cellsAcross) {
    return reachVoxels * frame.voxel + 0.5 * (cellsAcross - 1) * std::sqrt(3.0) * frame.voxel;
  };
  const double brickReach = reachFrom(brickEdge), quarterReach = reachFrom(brickEdge / 2);
  const auto within = [&](const glm::dvec3& p, double reach) {
    return bvh.closest(p, reach).triangle != TriangleBvh::kNoTriangle ||
           (fans.tree && fans.tree->closest(p, reach + fans.beyond).triangle != TriangleBvh::kNoTriangle);
  };
  std::vector<uint8_t> near(grid.cells(), 0);
  const interrupt::Watch stop;  // the threads below are not the call's
#pragma omp parallel for schedule(dynamic, 64)
  for (size_t b = 0; b < grid.cells(); ++b) {
    if (b % 256 == 0 && stop.requested()) continue;  // the caller stops after the loop
    const glm::ivec3 brick(int(b % grid.nx), int(b / grid.nx % grid.ny), int(b / grid.nx / grid.ny));
    const glm::dvec3 first = glm::dvec3(brickEdge * brick);
    if (!within(frame.toWorld(first + 0.5 * (brickEdge - 1)), brickReach)) continue;
    for (int q = 0; q < 8 && !near[b]; ++q) {
      const glm::dvec3 quarter = first + glm::dvec3(q & 1, q >> 1 & 1, q >> 2 & 1) * double(brickEdge / 2);
      near[b] = within(frame.toWorld(quarter + 0.5 * (brickEdge / 2 - 1)), quarterReach);
    }
  }
  for (size_t b = 0; b < grid.cells(); ++b)
    if (near[b]) bricks->activate(int(b % grid.nx), int(b / grid.nx % grid.ny), int(b / grid.nx / grid.ny));
  return bricks;
}

// Unsigned distances (voxels) of the stored cells inside the grid, as the
// grid's signed distance makes them: exact within exactVoxels of the
// surface, closest-point propagation beyond (far_field.hpp) up to
// maxVoxels; +inf beyond that and beyond the grid.
std::vector<float> bandDistances(const TriangleBvh& bvh, const GridFrame& frame, const BandCells& cells,
                                 double exactVoxels, double maxVoxels, Progress* progress, SignedDistanceStats& s)
{
  std::vector<float> distance(cells.count(), std::numeric_limits<float>::infinity());
  std::vector<uint32_t> nearest(cells.count(), TriangleBvh::kNoTriangle);
  Stopwatch exact;
  s.bandCells = exactBandDistances(bvh, frame, cells, exactVoxels, distance, nearest, progress, 0.4);
  s.bandMs = exact.ms();
  interrupt::check("nothing was written");
  if (progress) progress->beginPart("far field", 1.0, 0.3);
  Stopwatch propagated;
  s.farCells = propagateFarField(bvh, frame, cells, distance, nearest, maxVoxels);
  s.farFieldMs = propagated.ms();
  return distance;
}

// The exact distance (voxels) of the grid's cells that have none yet;
// returns how many.
size_t exactWhereUnreached(const TriangleBvh& bvh, const GridFrame& frame, const BandCells& cells,
                           std::vector<float>& distance)
{
  size_t filled = 0;
#pragma omp parallel for schedule(dynamic, 4096) reduction(+ : filled)
  for (size_t i = 0; i < distance.size(); ++i) {
    if (std::isfinite(distance[i]) || !cells.real(i)) continue;
    const glm::ivec3 c = cells.coords(i);
    distance[i] = float(bvh.closest(frame.cellCentre(c.x, c.y, c.z)).distance / frame.voxel);
    ++filled;
  }
  return filled;
}

// Which side each inactive brick is on: the side of the active cell next to
// it (no surface lies between: the inactive brick's cells are all more than
// two voxels from it), spread from brick to brick; a region of inactive
// bricks that touches no active one (no surface near the grid) asks the
// winding number at one brick centre.
void markFarSides(BandField& band, const std::vector<uint8_t>& inside, const TriangleBvh& bvh, const GridFrame& frame)
{
  const BrickSet& bricks = band.bricks();
  const Extent3 grid = bricks.bricks();
  std::vector<int8_t>& side = band.farSides();
  std::fill(side.begin(), side.end(), int8_t(0));
  std::deque<glm::ivec3> queue;
  const glm::ivec3 steps[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (size_t s = 0; s < bricks.activeCount(); ++s) {
    const glm::ivec3 b = bricks.brick(int32_t(s));
    for (const glm::ivec3& d : steps) {
      const glm::ivec3 n = b + d;
      if (!grid.contains(n.x, n.y, n.z) || bricks.slot(n.x, n.y, n.z) != noBrick) continue;
      int8_t& mark = side[grid.index(n.x, n.y, n.z)];
      if (mark != 0) continue;
      // The cell of brick b on the shared face, in its middle.
      glm::ivec3 local(brickEdge / 2);
      for (int a = 0; a < 3; ++a)
        if (d[a] != 0) local[a] = d[a] > 0 ? brickEdge - 1 : 0;
      glm::ivec3 cell = brickEdge * b + local;
      cell = glm::min(cell, glm::ivec3(bricks.cells().nx, bricks.cells().ny, bricks.cells().nz) - 1);
      const int64_t i = bricks.storedIndex(cell.x, cell.y, cell.z);
      mark = i >= 0 && inside[size_t(i)] ? int8_t(1) : int8_t(-1);
      queue.push_back(n);
    }
  }
  auto flood = [&] {
    while (!queue.empty()) {
      const glm::ivec3 b = queue.front();
      queue.pop_front();
      for (const glm::ivec3& d : steps) {
        const glm::ivec3 n = b + d;
        if (!grid.contains(n.x, n.y, n.z) || bricks.slot(n.x, n.y, n.z) != noBrick) continue;
        int8_t& mark = side[grid.index(n.x, n.y, n.z)];
        if (mark != 0) continue;
        mark = side[grid.index(b.x, b.y, b.z)];
        queue.push_back(n);
      }
    }
  };
  flood();
  for (int z = 0; z < grid.nz; ++z)
    for (int y = 0; y < grid.ny; ++y)
      for (int x = 0; x < grid.nx; ++x) {
        int8_t& mark = side[grid.index(x, y, z)];
        if (mark != 0 || bricks.slot(x, y, z) != noBrick) continue;
        const glm::dvec3 centre = frame.toWorld(glm::dvec3(brickEdge * glm::ivec3(x, y, z)) + 0.5 * (brickEdge - 1));
        mark = bvh.windingNumber(centre) > 0.5 ? int8_t(1) : int8_t(-1);
        queue.emplace_back(x, y, z);
        flood();
      }
}

}  // namespace

std::shared_ptr<BrickSet> bricksNearSurface(const TriangleMesh& mesh, const TriangleBvh& tree, const GridFrame& frame,
                                            double reachVoxels, bool overHoles)
{
  checkSignedDistanceArguments(mesh, frame, 1.0);
  return bandBricks(tree, overHoles ? fanReach(mesh, tree, frame, reachVoxels - 2.0) : FanReach{}, frame, reachVoxels);
}

namespace {

// signedDistanceOn(), given how long the tree took to build when it was
// built for it (signedDistanceBand()).
BandField distancesOnBricks(const TriangleMesh& mesh, const TriangleBvh& bvh, double treeMs, const GridFrame& frame,
                            std::shared_ptr<const BrickSet> given, const BandDistanceOptions& options,
                            SignedDistanceStats* stats)
{
  checkSignedDistanceArguments(mesh, frame, 1.0);
  SignedDistanceStats local;
  SignedDistanceStats& s = stats ? *stats : local;
  s = SignedDistanceStats{};
  s.triangles = mesh.triangles.size();
  const Stopwatch total;
  const auto beginPart = [&](const char* part, double weight) {
    if (options.progress) options.progress->beginPart(part, 1.0, weight);
  };

  Stopwatch stage;
  const std::shared_ptr<const BrickSet> bricks =
      given ? given
            : bandBricks(bvh, options.overHoles ? fanReach(mesh, bvh, frame, options.halfWidth) : FanReach{}, frame,
                         options.halfWidth + 2.0);
  s.bvhMs = treeMs + stage.ms();
  interrupt::check("nothing was written");
  if (options.checkBricks) options.checkBricks(*bricks);

  stage.restart();
  const BandCells cells(*bricks);
  s.cells = cells.count();
  // Only the cells that stream need their distance: the lattice holds the
  // others fixed, and they decide nothing within the half width until as
  // many steps as it has voxels (band_width.hpp). They get the clamped
  // value halfWidth + 1 on their side.
  const double clamped =
      options.clampBeyondHalfWidth ? options.halfWidth + 1.0 : std::numeric_limits<double>::infinity();
  std::vector<float> distance;
  const UnsignedBandDistances elsewhere = options.distancesFrom ? options.distancesFrom(bvh) : UnsignedBandDistances{};
  if (elsewhere) {
    if (options.progress) options.progress->beginPart("distances on the device", 1.0, 0.7);
    distance = elsewhere(bvh, frame, cells, clamped);
    interrupt::check("nothing was written");
    s.bandCells = size_t(std::count_if(distance.begin(), distance.end(), [](float d) { return std::isfinite(d); }));
    s.bandMs = stage.ms();
    s.onDevice = true;
  } else {
    distance = bandDistances(bvh, frame, cells, 3.0, clamped, options.progress, s);
  }

  // Unclamped (a morph's two fields), every cell of the grid needs its
  // distance, but propagation only spreads through bricks joined to the
  // surface's: a morph whose shapes lie apart stores the target's bricks
  // out of the source's reach, and they were left infinite (the morph
  // failed: "the field holds a value that is not a finite number").
  if (std::isinf(clamped)) s.farCells += exactWhereUnreached(bvh, frame, cells, distance);

  stage.restart();
  beginPart("winding-number sign", 0.2);
  const WindingGradientBound gradient(mesh);
  s.openEdges = gradient.openEdgeCount();
  const std::vector<uint8_t> inside =
      insideByWindingNumber(bvh, gradient, frame, cells, distance, s.windingEvaluations);
  s.signMs = stage.ms();

  // Cells of the last bricks that lie beyond the grid are never read; they
  // hold the far value of their side, like cells of inactive bricks.
  const float farValue = float(options.halfWidth + 2.0 + (brickEdge - 1) * std::sqrt(3.0));
  BandField band(bricks, farValue);
  std::vector<float>& values = band.values();
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < values.size(); ++i) {
    const float d = std::isfinite(distance[i]) ? std::min(distance[i], float(clamped))
                    : cells.real(i)            ? float(clamped)
                                               : farValue;
    values[i] = inside[i] ? d : -d;
  }
  markFarSides(band, inside, bvh, frame);
  s.totalMs = treeMs + total.ms();
  log::verbose("band distances: " + std::to_string(bricks->activeCount()) + " bricks; hierarchy and bricks " +
               std::to_string(int(s.bvhMs)) + " ms, " + std::to_string(s.bandCells) + " exact distances " +
               (s.onDevice ? "on the device " : "") + std::to_string(int(s.bandMs)) + " ms, " +
               std::to_string(s.farCells) + " propagated " + std::to_string(int(s.farFieldMs)) + " ms, sign " +
               std::to_string(int(s.signMs)) + " ms (" + std::to_string(s.windingEvaluations) + " evaluations), all " +
               std::to_string(int(s.totalMs)) + " ms");
  return band;
}

}  // namespace

bool surfaceLeavesTheBand(const BandField& band)
{
  const BrickSet& bricks = band.bricks();
  const Extent3 grid = bricks.bricks(), cells = bricks.cells();
  const std::vector<float>& values = band.values();
  bool leaves = false;
#pragma omp parallel for schedule(dynamic, 64) reduction(|| : leaves)
  for (size_t s = 0; s < bricks.activeCount(); ++s) {
    if (leaves) continue;
    const glm::ivec3 b = bricks.brick(int32_t(s));
    for (int axis = 0; axis < 3 && !leaves; ++axis)
      for (int direction : {-1, 1}) {
        glm::ivec3 n = b;
        n[axis] += direction;
        if (!grid.contains(n.x, n.y, n.z) || bricks.slot(n.x, n.y, n.z) != noBrick) continue;
        const bool beyondInside = band.farSide(n.x, n.y, n.z) > 0;
        // The brick's face towards n: cell coordinate 0 or 7 along the axis.
        const int layer = direction > 0 ? brickEdge - 1 : 0;
        for (int u = 0; u < brickEdge && !leaves; ++u)
          for (int v = 0; v < brickEdge; ++v) {
            glm::ivec3 local;
            local[axis] = layer;
            local[(axis + 1) % 3] = u;
            local[(axis + 2) % 3] = v;
            const glm::ivec3 c = brickEdge * b + local;
            if (!cells.contains(c.x, c.y, c.z)) continue;
            if ((values[s * brickCells + size_t(cellInBrick(local.x, local.y, local.z))] > 0.0f) != beyondInside) {
              leaves = true;
              break;
            }
          }
      }
  }
  if (leaves) return true;
  // Or runs between two inactive bricks, along their shared face, where no
  // cell is stored to mark it (each took its side from the active brick
  // next to it, on either side of the surface).
  const std::vector<int8_t>& sides = band.farSides();
#pragma omp parallel for schedule(static) reduction(|| : leaves)
  for (int z = 0; z < grid.nz; ++z)
    for (int y = 0; y < grid.ny; ++y)
      for (int x = 0; x < grid.nx; ++x) {
        if (bricks.slot(x, y, z) != noBrick) continue;
        const int8_t side = sides[grid.index(x, y, z)];
        const glm::ivec3 next[3] = {{x + 1, y, z}, {x, y + 1, z}, {x, y, z + 1}};
        for (const glm::ivec3& n : next)
          if (grid.contains(n.x, n.y, n.z) && bricks.slot(n.x, n.y, n.z) == noBrick &&
              sides[grid.index(n.x, n.y, n.z)] != side)
            leaves = true;
      }
  return leaves;
}

BandField signedDistanceBand(const TriangleMesh& mesh, const GridFrame& frame, const BandDistanceOptions& options,
                             SignedDistanceStats* stats)
{
  checkSignedDistanceArguments(mesh, frame, 1.0);
  if (!(options.halfWidth >= 1.0) || !std::isfinite(options.halfWidth))
    throw UsageError("the band's half width must be at least 1 voxel");
  if (options.progress) options.progress->beginPart("hierarchy", 1.0, 0.1);
  const Stopwatch hierarchy;
  const TriangleBvh tree(mesh);
  return distancesOnBricks(mesh, tree, hierarchy.ms(), frame, nullptr, options, stats);
}

BandField signedDistanceOn(const TriangleMesh& mesh, const TriangleBvh& tree, const GridFrame& frame,
                           std::shared_ptr<const BrickSet> bricks, const BandDistanceOptions& options,
                           SignedDistanceStats* stats)
{
  return distancesOnBricks(mesh, tree, 0.0, frame, std::move(bricks), options, stats);
}

}  // namespace lbmshape
