// What a grid loses of a shape without the distances showing it: parts or
// gaps thinner than about two voxels, cut off or closed (a horse's hooves at
// --res 48, a horse a few voxels long in a morph). Compared by parts and
// genus, which the user should not have to find by looking.
#pragma once

#include <string>

#include "lbmshape/analysis/mesh_topology.hpp"

namespace lbmshape {

// A warning when both are closed and `made` ("the result", "the last frame")
// has other parts or another genus than `wanted` ("the input", "the
// target"), naming the voxel and the finer grid that would keep them.
void warnIfThePartsChanged(const MeshTopology& wanted, const std::string& wantedName, const MeshTopology& made,
                           const std::string& madeName, double voxel);

}  // namespace lbmshape
