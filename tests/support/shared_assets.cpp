#include "support/shared_assets.hpp"

#include <cstdlib>

namespace lbmshape::testing {

std::filesystem::path sharedAsset(const std::string& name)
{
  // The environment may point elsewhere; by default, ../shared/assets beside
  // the source tree, as configured.
  const char* folder = std::getenv("LBMSHAPE_SHARED_ASSETS");
  if (!folder || !*folder) folder = LBMSHAPE_DEFAULT_SHARED_ASSETS;
  std::filesystem::path path = std::filesystem::path(folder) / name;
  return std::filesystem::exists(path) ? path : std::filesystem::path();
}

}  // namespace lbmshape::testing
