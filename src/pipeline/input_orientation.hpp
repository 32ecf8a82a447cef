// An input mesh turned as the winding number's sign needs it
// (sdf/shell_orientation.hpp) before its distances are computed, saying what
// was turned: a malformed export then gives the shape it was meant to be,
// with a warning, instead of fragments or a misleading refusal.
#pragma once

#include <string>

#include "analysis/mesh_topology.hpp"
#include "mesh/triangle_mesh.hpp"

namespace lbmshape {

// Turns `mesh` where it needs it (a warning naming `name` says how much),
// and returns its topology as turned.
MeshTopology orientTheInput(TriangleMesh& mesh, const std::string& name);

}  // namespace lbmshape
