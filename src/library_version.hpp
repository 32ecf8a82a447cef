// The version of the lbmshape library a program runs with; the one it was
// built against is LBMSHAPE_LIBRARY_VERSION in lbmshape/version.hpp.
#pragma once

namespace lbmshape {

const char* libraryVersion();

}  // namespace lbmshape
