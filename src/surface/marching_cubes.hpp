// Iso-surface extraction: the last stage of the pipeline turns the field X
// back into a triangle mesh (marching cubes over the cell centres).
#pragma once

#include "lbmshape/core/volume.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/sdf/grid_frame.hpp"

namespace lbmshape {

// The surface X = isovalue of `field`, sampled at the cell centres of `frame`,
// with X > isovalue inside. A sample exactly equal to the isovalue counts as
// outside, so a field that touches the isovalue without crossing it gives no
// surface there.
//
// The mesh has world positions (through `frame`), one vertex per grid edge the
// surface cuts, kept at least 0.001 of the edge away from its ends so that no
// two vertices coincide and no triangle has zero area. Triangles are wound
// counter-clockwise seen from outside, so their normals point from X > iso to
// X < iso. The per-vertex normals are -grad X (central differences at the two
// ends of the edge, interpolated), normalised.
//
// When no cell on the outer layer of the grid is inside, the mesh is a closed
// 2-manifold with consistent orientation and positive volume: every edge has
// two triangles and every vertex a single fan of them, at saddles and where
// two parts touch too. Otherwise it is open where the surface leaves the grid.
// The result does not depend on the number of threads.
//
// Throws std::invalid_argument when frame.extent differs from the field's,
// UsageError for a non-finite isovalue, NumericalError when the field holds a
// NaN or an infinity.
TriangleMesh extractSurface(const Volume& field, const GridFrame& frame, float isovalue = 0.0f);

}  // namespace lbmshape
