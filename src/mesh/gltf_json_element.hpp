// What the first pass over a glTF file's JSON (gltf_json_check.hpp) notes of
// one element of a glTF array (a node, an accessor, a primitive...), and the
// types glTF gives the properties lbmshape reads from it. tinygltf reads a
// property of the wrong type as absent: a node whose "mesh" is the string
// "0", or whose translation is ["a", 0, 0] or twelve numbers for a matrix,
// was placed at the origin with no mesh, and an accessor's negative
// byteOffset read as 0, so a malformed file gave another shape and exit 0.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "lbmshape/mesh/mesh_source.hpp"

namespace lbmshape {

struct GltfJsonElement {
  struct Array {
    uint64_t count = 0;
    bool allNumbers = true, allWholeNumbers = true;  // whole: integers of 0 or more
  };
  std::map<std::string, std::string> written;  // every property, as written (arrays and objects named, not copied)
  std::map<std::string, uint64_t> wholeNumbers;
  std::map<std::string, std::string> strings;
  std::map<std::string, Array> arrays;
};

// The arrays whose elements are checked, as dotted paths from the top
// level: "nodes", "meshes.primitives"...
bool isCheckedGltfCollection(const std::string& collection);

// Throws InputError naming `source` and the element (`index` holds its
// place in each array of its path) when a property glTF defines as an
// index, count or offset is not a whole number of 0 or more, a transform is
// not an array of as many numbers as it needs, a node has a matrix beside
// translation, rotation or scale, or a primitive's mode is not one of glTF's.
void checkGltfElement(const std::string& collection, const std::vector<uint64_t>& index, const GltfJsonElement& element,
                      const MeshSource& source);

}  // namespace lbmshape
