// How far from its triangles the surface that closes an open mesh's holes
// may lie, for a narrow band that must hold it.
//
// The winding number's sign gives an open mesh an inside
// (sdf/winding_sign.hpp): over each hole its level 1/2 spans the hole's
// rim like a soap film, where no triangle is near. A band holds only the
// cells near the triangles, so a hole wider than the band left the result
// open there (a hemisphere's rim, a scan's hole 40 voxels across), and a
// morph to such a target ended on a shape with holes while its fields said
// it had arrived. A band wider than the widest hole's radius holds the
// whole film, as the dense grid does.
#pragma once

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

}  // namespace lbmshape
