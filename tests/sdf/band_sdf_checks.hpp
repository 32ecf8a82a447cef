// The check that the narrow band's signed distance holds the grid's field
// wherever the lattice needs it, for the tests on built shapes and on the
// shared meshes.
#pragma once

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// On a grid of `resolution` cells (margin 3): every cell within
// halfWidth + 2 of the surface is held, with the grid's value (within 1e-5
// inside the exact band, 0.2 beyond), every held or far cell is on the
// grid's side, and no brick is held for nothing.
void expectBandHoldsTheGridsField(const TriangleMesh& mesh, int resolution, double halfWidth);

}  // namespace lbmshape
