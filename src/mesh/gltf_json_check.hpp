// A first pass over a glTF file's JSON, before tinygltf parses it: tinygltf
// (and nlohmann's json, which it uses) recurse once per level of nesting, so
// a file nested 50,000 deep would overflow the stack inside them. This pass
// is nlohmann's SAX parser, which does not recurse: it refuses nesting
// beyond what any real glTF file needs and notes what the reader must know
// before tinygltf touches the file system: the buffers' URIs and sizes.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/mesh_source.hpp"

namespace lbmshape {

// Real glTF files nest about 10 deep (extensions included).
inline constexpr int maxGltfJsonDepth = 64;

struct GltfBufferEntry {
  std::string uri;  // as written in the file; empty for a GLB's own binary chunk
  uint64_t byteLength = 0;
};

// Throws InputError naming `source` when `json` is not JSON or nests deeper
// than maxGltfJsonDepth. The buffers array is read as far as it is well
// formed; tinygltf checks the rest.
std::vector<GltfBufferEntry> checkGltfJson(std::string_view json, const MeshSource& source);

}  // namespace lbmshape
