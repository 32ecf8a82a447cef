// Reading GLB files compressed with EXT_meshopt_compression (what
// `--compress` and gltfpack write): before the rest of the glTF reader sees
// the file, every compressed buffer view is decoded with meshoptimizer's
// decoders into the binary chunk, so that the file becomes a plain GLB
// (KHR_mesh_quantization's integer attributes the accessors read as they are).
// The file is untrusted like any other: every field is checked, decoders
// report malformed data instead of reading past it, and what is decoded is
// bounded by a multiple of the file's size.
#pragma once

#include <optional>
#include <string>

#include "lbmshape/mesh/mesh_source.hpp"

namespace lbmshape {

// The decoded GLB, or nothing when the file does not use the extension.
// InputError (through source.refuse) for anything malformed.
std::optional<std::string> decodeMeshoptGlb(const MeshSource& source, std::string_view json, std::string_view binary);

}  // namespace lbmshape
