// Pictures as PNG files, written atomically like every output of lbmshape.
#pragma once

#include <filesystem>

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/render/image.hpp"

namespace lbmshape::render {

// Encodes `image` into the file's temporary name and commits it; a failed
// write (full disk, no permission) is an OutputError naming the target, and
// leaves nothing under it.
void writePng(const Image& image, AtomicFile& file);

// Throws UsageError unless `path` ends in .png (in any letter case), naming
// `what` (the option or argument that gave it).
void requirePngPath(const std::filesystem::path& path, const std::string& what);

}  // namespace lbmshape::render
