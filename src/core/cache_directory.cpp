#include "lbmshape/core/cache_directory.hpp"

#include <cstdlib>

namespace lbmshape {

std::filesystem::path userCacheDirectory()
{
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "lbmshape";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "lbmshape";
  return {};
}

}  // namespace lbmshape
