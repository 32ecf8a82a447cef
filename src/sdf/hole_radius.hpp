// How far from its triangles the surface that closes an open mesh's holes
// may lie, for a narrow band that must hold it.
//
// The winding number's sign gives an open mesh an inside
// (sdf/winding_sign.hpp): over each hole its level 1/2 spans the hole's
// rim like a soap film, where no triangle is near. A band holds only the
// cells near the triangles, so a hole wider than the band left the result
// open there (a hemisphere's rim, a scan's hole 40 voxels across), and a
// morph to such a target ended on a shape with holes while its fields said
// it had arrived. The band reaches the fans over the rims (closingFans
// below), which hold a planar rim's film exactly and most others' nearly;
// where the film still leaves the band (a rim far out of its plane, a film
// pulled aside by the rest of the mesh), a band wider than the widest
// hole's radius holds it, as the dense grid does.
#pragma once

#include <functional>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// The radius of the mesh's widest hole, in its own units; 0 for a closed
// mesh. A hole is a rim: the edges that one triangle runs one way more
// often than others run it back (vertices joined by index, as
// orientTheInput leaves them), joined through shared vertices. Its radius
// is the farthest of its vertices from their centroid, which is how far a
// planar rim's film (its disk) lies from the rim at most.
double widestHoleRadius(const TriangleMesh& mesh);

// The band's half width (voxels) that holds the film over every hole of
// `mesh` as well as `halfWidth` does the surface: the widest hole's radius
// with a quarter more for a film that bulges out of its rim's plane, and
// the voxel the lattice's neighbours need.
double halfWidthOverHoles(const TriangleMesh& mesh, double voxel, double halfWidth);

// Where the film over each hole lies, to a first guess: a fan of triangles
// from each rim's edges to the centroid of its vertices, for the band to
// reach there as it reaches the triangles (band_signed_distance.cpp). For a
// planar rim alone (a hemisphere's) the film is exactly that disk: the
// winding number of a point on it is 1/2. A film bulges out of its rim's
// plane at most as far as the rim does, in the usual case that the rest of
// the mesh does not pull it further; farthestOffPlane says how far the rims
// do, and a band that still leaves is widened as before.
struct ClosingFans {
  TriangleMesh mesh;              // no triangles for a closed mesh
  double farthestOffPlane = 0.0;  // in the mesh's units: a rim vertex from its fan's plane
};
// A rim gets none where its fan covers no more than `leastArea` (the
// mesh's units squared), where it leaves its fan's plane by more than the
// radius of a disk of the fan's area, or, given the mesh's winding number,
// where that is not within 1/4 of 1/2 at the fan's centre (a crack between
// pieces, not a hole).
using WindingAt = std::function<double(const glm::dvec3&)>;
ClosingFans closingFans(const TriangleMesh& mesh, double leastArea = 0.0, const WindingAt& windingAt = {});

}  // namespace lbmshape
