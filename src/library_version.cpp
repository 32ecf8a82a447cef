#include "library_version.hpp"

namespace lbmshape {

const char* libraryVersion() { return LBMSHAPE_VERSION; }

}  // namespace lbmshape
