// The Khronos glTF-Validator, run on a file from a test. It is the npm
// package in tests/gltf_validator (installed there by `npm ci`, which
// scripts/test.sh does), run by Node through validate.mjs.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lbmshape::testing {

struct GltfValidation {
  int errors = 0, warnings = 0, infos = 0, hints = 0;
  std::vector<std::string> messages;  // "warning CODE at /pointer: text", every severity
  std::string failure;                // why the validator could not run; empty when it did

  // The validator ran and found no error and no warning.
  bool passed() const { return failure.empty() && errors == 0 && warnings == 0; }
};

GltfValidation validateGltf(const std::filesystem::path& file);

// What three.js's GLTFLoader (with its meshopt decoder, as a web viewer
// sets it up) makes of a .glb file: three_load.mjs's JSON ("meshes",
// "triangles", "min", "max", "animations"), or the reason it could not
// load it in `failure`.
struct ThreeJsLoad {
  nlohmann::json scene;
  std::string failure;
};
ThreeJsLoad loadWithThreeJs(const std::filesystem::path& file);

// For assertion messages: EXPECT_TRUE(v.passed()) << v;
std::ostream& operator<<(std::ostream& out, const GltfValidation& validation);

}  // namespace lbmshape::testing
