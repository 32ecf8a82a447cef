// Compressed files, told by their first bytes: a mesh that was gzipped or
// zipped is refused as such, where each reader found a damaged file.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "lbmshape/mesh/mesh_source.hpp"

namespace lbmshape {

// "gzip", "zip", "bzip2", "xz", "zstd" or "7-zip" when `bytes` begins as
// that kind of file does.
std::optional<std::string> compressionOf(std::string_view bytes);

// Throws InputError naming `source` when its bytes are compressed.
void refuseCompressed(const MeshSource& source);

}  // namespace lbmshape
