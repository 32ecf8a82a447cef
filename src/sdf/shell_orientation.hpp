// What the winding number's sign needs of a surface: every triangle wound
// as its neighbours are, and each closed shell facing out unless it is a
// cavity inside another. A scan exported with some triangles reversed, or a
// part that is inside out (a mirrored CAD part, an inward-facing export),
// would otherwise have a garbled inside or none (winding number -1 or 0
// where it is solid): the result would be a few fragments, or a refusal that
// blamed the resolution.
#pragma once

#include <cstddef>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

struct Reorientation {
  size_t trianglesTurned = 0;  // to agree with their neighbours
  size_t shellsTurned = 0;     // closed shells that faced in, inside no other shell
  // Closed shells inside a shell turned above that faced the wrong way for
  // their depth (a mirrored hollow part's cavity).
  size_t nestedShellsTurned = 0;
  size_t openPiecesTurned = 0;  // open pieces inside out (a mirrored scan)
  // Edges whose two triangles could not be made to agree (a Möbius strip,
  // a Klein bottle): left as they were.
  size_t unorientableEdges = 0;
  bool changed() const
  {
    return trianglesTurned > 0 || shellsTurned > 0 || nestedShellsTurned > 0 || openPiecesTurned > 0;
  }
};

// Across every edge that exactly two triangles share, turns triangles over
// (their second and third corners swapped) so that the two run the edge in
// opposite directions; in each piece so joined, the orientation most of its
// triangles had wins. Then turns over each closed piece whose volume is
// negative unless a point of it lies inside the other pieces (|winding
// number| >= 1/2): a cavity's inward shell stays, as it is meant; and the
// closed pieces inside a shell so turned face in or out by their depth
// among them (it was mirrored, with them). Then turns over each open piece
// whose own winding number at its corners' centroid is -1/2 or less.
Reorientation orientShells(TriangleMesh& mesh);

}  // namespace lbmshape
