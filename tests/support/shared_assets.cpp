#include "support/shared_assets.hpp"

#include <cstdlib>

namespace lbmshape::testing {

std::filesystem::path sharedAsset(const std::string& name)
{
  const char* folder = std::getenv("LBMSHAPE_SHARED_ASSETS");
  if (!folder || !*folder) return {};
  std::filesystem::path path = std::filesystem::path(folder) / name;
  return std::filesystem::exists(path) ? path : std::filesystem::path();
}

}  // namespace lbmshape::testing
