// Marching cubes puts a vertex wherever the surface crosses a grid edge, so
// its triangles follow the grid rather than the surface: on a denoised scan
// at --res 128 a tenth of them are slivers (an angle under 10 degrees),
// whose normals are the least accurate of all. Relaxation moves every
// vertex towards the centre of its neighbours, within its tangent plane:
// the triangles even out (the slivers all but vanish) and their normals
// come nearer the surface's, while the surface stays where it was (a move
// of a fraction of a voxel along the surface leaves it by its square times
// the curvature). docs/denoising.md, "Relaxed triangles", has the figures.
#pragma once

#include <cstddef>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// The rounds denoise runs by default: the second round adds a little to
// the first, a third nothing measurable.
inline constexpr int defaultRelaxationRounds = 2;
// The most rounds accepted (parameter_bounds): beyond a few, nothing changes.
inline constexpr int maxRelaxationRounds = 100;

struct RelaxationSummary {
  size_t movedVertices = 0;  // vertices moved in the last round
  size_t keptVertices = 0;   // in the last round, kept where they were so that no triangle turned over
};

// `rounds` rounds of tangential relaxation: half the way to the centre of
// the vertex's neighbours within its tangent plane, then back onto the
// surface by the bend that the normals show (to second order). The normal
// is the mesh's where it has them (marching cubes': the field's gradient),
// else its triangles' (area-weighted); the mesh's normals move with their
// vertices, half the way to their neighbours'. The triangles are not
// changed, only the positions, so a closed manifold stays one. A vertex
// whose triangles do not close around it (on the rim of a hole) stays put;
// the test, cheap and exact for one open fan, can be fooled by a vertex
// where several open fans meet, and a vertex where closed fans touch
// moves, neither of which marching cubes makes. A move that would turn a
// triangle over (or flatten it) is not made. Throws std::invalid_argument
// on a position that is not finite.
RelaxationSummary relaxTriangles(TriangleMesh& mesh, int rounds);

}  // namespace lbmshape
