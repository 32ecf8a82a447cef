// What a grid loses of a shape without the distances showing it: parts or
// gaps thinner than about two voxels, cut off or closed (a horse's hooves at
// --res 48, a horse a few voxels long in a morph). Compared by parts and
// genus, which the user should not have to find by looking.
#pragma once

#include <cstddef>
#include <string>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// The parts of the solid a closed mesh encloses: its outward components,
// those that reach into one another counting as one (the winding number's
// inside is their union: a bolt modelled as a head and a shaft that
// overlap is one solid), and each inward one (a cavity) on its own.
size_t solidParts(const TriangleMesh& mesh);

// A warning when both are closed and `made` ("the result", "the last frame")
// has other parts or another genus than `wanted` ("the input", "the
// target"; its mesh `wantedMesh`), naming the voxel and the finer grid that
// would keep them. Where `wanted`'s components overlap, `made` is held to
// their union: as many parts as solidParts(), and any genus (the union's
// is not the sum of its parts').
void warnIfThePartsChanged(const TriangleMesh& wantedMesh, const MeshTopology& wanted, const std::string& wantedName,
                           const MeshTopology& made, const std::string& madeName, double voxel);

}  // namespace lbmshape
