// The signed distance field of a triangle mesh on a grid, in the convention
// of the paper: positive inside, negative outside, in voxels (the lattice's
// diffusion coefficient is in voxels^2 per step).
//
// Inside means generalized winding number above 1/2, so meshes with holes,
// several overlapping components or self-intersections still get a sensible
// solid. Distances are exact (to the triangles, in double precision) for
// every cell within options.bandVoxels of the surface; farther out they come
// from closest-triangle propagation (see far_field.hpp), or are exact
// everywhere with options.exactEverywhere.
#pragma once

#include <cstddef>

#include "lbmshape/core/progress.hpp"
#include "lbmshape/core/volume.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/sdf/grid_frame.hpp"

namespace lbmshape {

struct SignedDistanceOptions {
  double bandVoxels = 3.0;       // exact distances within this many voxels of the surface; at least 1
  bool exactEverywhere = false;  // exact far field too: slower, for checks and small grids
  Progress* progress = nullptr;  // told each part of the work as it starts, and the band's blocks as they finish
};

struct SignedDistanceStats {
  // Wall-clock milliseconds per stage.
  double bvhMs = 0.0;       // hierarchy and winding-number expansions
  double bandMs = 0.0;      // exact distances near the surface
  double signMs = 0.0;      // inside/outside from the winding number
  double farFieldMs = 0.0;  // distances of the remaining cells
  double totalMs = 0.0;
  size_t cells = 0;
  size_t triangles = 0;
  size_t bandCells = 0;           // cells given an exact distance by the band stage
  size_t farCells = 0;            // cells farther than the band
  size_t windingEvaluations = 0;  // fast winding-number queries made by the sign stage
  size_t openEdges = 0;           // uncancelled directed edges (hole rims), where w may vary off the surface
  bool onDevice = false;          // the distances computed on the device (BandDistanceOptions::distancesFrom)
};

// The checks both signed distances make first: InputError for a mesh
// without triangles, UsageError for an empty or too large frame or an exact
// band under one voxel.
void checkSignedDistanceArguments(const TriangleMesh& mesh, const GridFrame& frame, double bandVoxels);

// Throws InputError for a mesh without triangles or with bad indices or
// positions, and UsageError for an empty frame or a band under one voxel.
Volume signedDistance(const TriangleMesh& mesh, const GridFrame& frame, const SignedDistanceOptions& options = {},
                      SignedDistanceStats* stats = nullptr);

}  // namespace lbmshape
