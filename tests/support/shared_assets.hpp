// The shared test meshes (../shared/assets): present in CI and for the
// developers, absent from a user's clone. Tests that need them call
// requireSharedAsset(), which skips the test, saying why, when it is missing.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace lbmshape::testing {

// Path of a shared mesh, or empty if the folder is not there.
std::filesystem::path sharedAsset(const std::string& name);

#define LBMSHAPE_REQUIRE_SHARED_ASSET(var, name)                            \
  const std::filesystem::path var = ::lbmshape::testing::sharedAsset(name); \
  if (var.empty())                                                          \
  GTEST_SKIP() << "shared test mesh " << (name)                             \
               << " not found (clone ../shared beside the repository or set LBMSHAPE_SHARED_ASSETS): skipped"

}  // namespace lbmshape::testing
