#include "lbmshape/core/cache_directory.hpp"

#include <cstdlib>

namespace lbmshape {

std::filesystem::path userCacheDirectory()
{
  // A relative XDG_CACHE_HOME is invalid (the XDG base directory
  // specification): ignored, not made in the job's working folder.
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && std::filesystem::path(xdg).is_absolute())
    return std::filesystem::path(xdg) / "lbmshape";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "lbmshape";
  return {};
}

}  // namespace lbmshape
