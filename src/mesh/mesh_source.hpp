// The bytes of one mesh file as a reader sees them: where they came from (for
// messages) and, for glTF, the folder its external buffers may be read from.
// Readers take a MeshSource rather than a path so that a program holding a
// file in memory (and the fuzz targets) can read it without a temporary file.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "lbmshape/core/error.hpp"

namespace lbmshape {

struct MeshSource {
  std::string_view bytes;
  std::string name;  // the path, or any label, as it appears in messages
  // The only folder a glTF file's buffer URIs may name files in; without it
  // only data: URIs and a GLB's own binary chunk are read.
  std::optional<std::filesystem::path> folder;

  // An InputError "cannot read NAME: WHY", the one way readers report a fault.
  [[noreturn]] void refuse(const std::string& why) const { throw InputError("cannot read " + name + ": " + why); }
};

}  // namespace lbmshape
