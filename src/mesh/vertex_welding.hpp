// Turning separate triangle corners (as STL stores them) into a mesh with
// shared vertices.
#pragma once

#include <vector>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// Corners 3t, 3t+1, 3t+2 make triangle t. Corners at exactly the same
// position (0 and -0 count as equal) become one vertex; vertices are numbered
// in the order their positions are first met; NaN positions are never
// merged. At most 2^32 - 1 corners.
TriangleMesh weldEqualPositions(const std::vector<glm::dvec3>& corners);

}  // namespace lbmshape
