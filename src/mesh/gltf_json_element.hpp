// What the first pass over a glTF file's JSON (gltf_json_check.hpp) notes of
// one element of the file (the top-level object, a node, an accessor, a
// primitive, its attributes...), and the types glTF gives the properties
// lbmshape's reading depends on. tinygltf reads a property of the wrong type
// as absent, or skips what holds it: a node whose "mesh" is the string "0",
// a translation of ["a", 0, 0] or twelve numbers for a matrix, an accessor's
// negative byteOffset, "normalized": "true", a primitive with an attribute
// of 0.5 (the whole primitive dropped), "scenes" as an object (every root
// node shown): each gave another shape and exit 0.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "lbmshape/mesh/mesh_source.hpp"

namespace lbmshape {

enum class JsonKind { Number, String, Boolean, Null, Array, Object };

struct GltfJsonElement {
  struct Array {
    uint64_t count = 0;
    // Of the values in it; whole: integers of 0 or more.
    bool allNumbers = true, allWholeNumbers = true, allStrings = true, allObjects = true;
  };
  std::map<std::string, JsonKind> kinds;       // every property's
  std::map<std::string, std::string> written;  // every property, as written (arrays and objects named, not copied)
  std::map<std::string, uint64_t> wholeNumbers;
  std::map<std::string, std::string> strings;  // of buffers only (their URIs)
  std::map<std::string, Array> arrays;
};

// Checked elements, as dotted paths of their keys from the top level
// ("nodes", "meshes.primitives", "accessors.sparse.indices"; "" for the
// top-level object), with their place in each array on the way.
// `inAnArray`: the element's object is an array's value, not an object's.
bool isCheckedGltfCollection(const std::string& collection, bool inAnArray);
std::string gltfElementName(const std::string& collection, const std::vector<uint64_t>& index);

// Throws InputError naming `source` and the element when a property has
// another JSON type than glTF gives it (an index, count or offset that is
// not a whole number of 0 or more, a transform that is not as many numbers
// as it needs, a flag that is not true or false, a list that is not an
// array of what it lists), a node has a matrix beside translation,
// rotation or scale, or a primitive's mode is not one of glTF's.
void checkGltfElement(const std::string& collection, const std::vector<uint64_t>& index, const GltfJsonElement& element,
                      const MeshSource& source);

}  // namespace lbmshape
