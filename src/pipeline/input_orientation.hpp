// An input mesh made what the winding number's sign needs before its
// distances are computed: corners at one position made one vertex where
// that closes edges the file's numbering left open (a soup, a glTF split at
// its seams), and triangles turned as sdf/shell_orientation.hpp says, with
// a warning that says what was turned. A malformed export then gives the
// shape it was meant to be instead of fragments or a misleading refusal.
#pragma once

#include <string>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// Joins and turns `mesh` where it needs it (a warning naming `name` says
// what was turned), and returns its topology as it then is.
MeshTopology orientTheInput(TriangleMesh& mesh, const std::string& name);

// Says, where the input named `name` is open (edges in one triangle only,
// after the joining), that the output is closed over its holes or rim
// (`closing`: "the result closes it", "the frames close it"): the
// winding number's sign gives it an inside all the same, and the output's
// "closed" would otherwise hide that the shape was completed. Called once
// the input is known to enclose something (a refusal stays one line).
void sayWhereTheInputIsOpen(const MeshTopology& topology, const std::string& name, const std::string& closing);

}  // namespace lbmshape
