// The signed distance field on the narrow band only: the bricks (band/) that
// hold a cell within halfWidth + 2 voxels of the surface, every cell of them
// with its exact distance and its sign; nothing is computed or stored for
// the rest of the grid, whose bricks are only marked inside or outside. Same
// convention as signedDistance(): positive inside, in voxels, inside meaning
// generalized winding number above 1/2.
//
// Why + 2: the lattice updates the cells within halfWidth of the surface,
// and each pulls from neighbours up to sqrt(2) voxels away, which must be
// stored too; marching cubes needs the cells within about 2 voxels.
#pragma once

#include <functional>
#include <vector>

#include "lbmshape/band/band_field.hpp"
#include "lbmshape/core/progress.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/sdf/grid_frame.hpp"
#include "lbmshape/sdf/signed_distance.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"

namespace lbmshape {

class BandCells;
// Unsigned distances (voxels) of every stored cell, exact up to maxVoxels
// and +inf beyond it and beyond the grid: deviceBandDistances()'s contract
// (device_band_distances.hpp).
using UnsignedBandDistances =
    std::function<std::vector<float>(const TriangleBvh&, const GridFrame&, const BandCells&, double maxVoxels)>;

struct BandDistanceOptions {
  double halfWidth = 9.0;  // voxels; at least 1
  // Cells beyond halfWidth + 1 get that value (on their side) instead of
  // their distance: a lattice that holds them fixed needs nothing more
  // (band_width.hpp), and it saves most of the work. A morph needs the true
  // distances between its two surfaces: off.
  bool clampBeyondHalfWidth = true;
  // The band reaches the films over an open mesh's holes too, through fans
  // over their rims (sdf/hole_radius.hpp). Off: the bricks near the
  // triangles only, for a caller whose band with the fans did not fit.
  bool overHoles = true;
  Progress* progress = nullptr;  // told each part of the work as it starts
  // Called with the bricks as soon as they are chosen, before anything is
  // computed or allocated for their cells: a caller that cannot hold them
  // throws here (ComputeDevice::checkBandFits).
  std::function<void(const BrickSet&)> checkBricks = {};
  // Where the unsigned distances from the mesh's tree come from: when this
  // is empty or gives an empty function, the CPU's exact band and far-field
  // propagation; else the function it gives (the device's, as
  // ComputeDevice::bandDistances chooses). The sign is the CPU's either way.
  std::function<UnsignedBandDistances(const TriangleBvh&)> distancesFrom = {};
};

// Throws like signedDistance(); UsageError for a half width under 1 voxel.
BandField signedDistanceBand(const TriangleMesh& mesh, const GridFrame& frame, const BandDistanceOptions& options = {},
                             SignedDistanceStats* stats = nullptr);

// The two halves of it, for a band that must hold more than one surface (a
// morph's source and target): the bricks with a cell within `reachVoxels`
// of the mesh, and the signed distance on given bricks (every cell of them;
// far value halfWidth + 2 + a brick's diagonal). `tree` is the mesh's own
// hierarchy (TriangleBvh(mesh), with winding numbers), built once by the
// caller for both halves and whatever else it asks of the mesh.
std::shared_ptr<BrickSet> bricksNearSurface(const TriangleMesh& mesh, const TriangleBvh& tree, const GridFrame& frame,
                                            double reachVoxels, bool overHoles = true);
BandField signedDistanceOn(const TriangleMesh& mesh, const TriangleBvh& tree, const GridFrame& frame,
                           std::shared_ptr<const BrickSet> bricks, const BandDistanceOptions& options = {},
                           SignedDistanceStats* stats = nullptr);

// Whether the zero level runs out of the band's bricks into the inactive
// ones: a cell on the face of an active brick whose side (inside or out)
// is not that of the inactive brick beyond, or two inactive bricks side by
// side on different sides. A closed surface's band never
// does (beyond it lies one side only); an open mesh's does where the
// surface that closes a hole (the winding number's) lies further from the
// triangles than the band reaches, and the result would be open there
// (sdf/hole_radius.hpp says how much wider a band holds it).
bool surfaceLeavesTheBand(const BandField& band);

}  // namespace lbmshape
