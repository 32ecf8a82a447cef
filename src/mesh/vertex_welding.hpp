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

// The mesh with corners at equal positions made one vertex (a triangle
// soup; a glTF split at its UV seams and sharp edges, or into a primitive
// per material, as Blender exports it), each vertex keeping the normal and
// colour of a corner there: the pieces the file's numbering cut apart are
// one surface again, which can be closed, face out as a whole and keep its
// volume.
TriangleMesh weldEqualPositions(const TriangleMesh& mesh);

}  // namespace lbmshape
