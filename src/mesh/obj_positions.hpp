// OpenMesh's OBJ reader parses coordinates as float and silently skips any
// `v` line it cannot parse ("v nan 0 0", "v 1,5 2 3"), which shifts every
// later vertex index onto the wrong vertex. OpenMesh still does the faces
// (polygons, negative indices, v/vt/vn triples); this reads the `v` lines a
// second time, as doubles, so that lbmshape keeps the file's full precision
// and can name the first line that is not a vertex with finite coordinates.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace lbmshape {

struct ObjPositions {
  std::vector<glm::dvec3> positions;  // every `v` line, in file order
  // "line 7: 'v nan 0 0' is not three finite coordinates": the first `v`
  // line that OpenMesh would skip or that holds NaN or infinity.
  std::optional<std::string> problem;
};

ObjPositions readObjPositions(const std::filesystem::path& path);

}  // namespace lbmshape
