#pragma once

#include <filesystem>

namespace lbmshape {

// $XDG_CACHE_HOME/lbmshape, or ~/.cache/lbmshape; empty if neither is known.
std::filesystem::path userCacheDirectory();

}  // namespace lbmshape
