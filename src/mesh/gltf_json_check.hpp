// A first pass over a glTF file's JSON, before tinygltf parses it. tinygltf
// (and nlohmann's json under it) recurse once per level of nesting, so a
// file nested 50,000 deep would overflow the stack inside them; they build
// hundreds of bytes of structures per JSON value, so 100 MB of "[0,0,...]"
// would take many gigabytes; and tinygltf trusts a few numbers it then reads
// memory by (an image's buffer view, a GLB's buffers). This pass is
// nlohmann's SAX parser, which does not recurse and builds nothing: it
// refuses all of that, and notes what the reader must know before tinygltf
// touches the file system: the buffers' URIs and sizes.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "lbmshape/mesh/mesh_source.hpp"

namespace lbmshape {

// Real glTF files nest about 10 deep (extensions included).
inline constexpr int maxGltfJsonDepth = 64;

struct GltfBufferEntry {
  std::string uri;  // as written in the file; empty for a GLB's own binary chunk
  uint64_t byteLength = 0;
};

// Throws InputError naming `source` when `json` is not JSON, nests deeper
// than maxGltfJsonDepth, holds more values than tinygltf could build in
// memory proportionate to the file, declares a buffer of 0 bytes or two
// buffers on one file, gives a GLB more than one buffer of its own (or not
// as buffer 0), has an image whose buffer view reaches past its buffer, a
// key twice in one object, a default scene it does not have, or an element
// property of the wrong type (gltf_json_element.hpp), or requires an
// extension lbmshape cannot read (Draco; meshopt outside a GLB) or does
// not know: that first, as a compressed file fails the other checks.
// Returns the buffers; tinygltf checks the rest.
std::vector<GltfBufferEntry> checkGltfJson(std::string_view json, bool glb, const MeshSource& source);

}  // namespace lbmshape
