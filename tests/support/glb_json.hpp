// The JSON chunk of a .glb file, for tests that check what lbmshape wrote
// into it (nodes, meshes, animation) without a glTF library.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

namespace lbmshape::testing {

nlohmann::json glbJson(const std::filesystem::path& path);

}  // namespace lbmshape::testing
