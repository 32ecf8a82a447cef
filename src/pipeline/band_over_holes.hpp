// The band that reaches the film over an open input's holes (fans over
// their rims, sdf/hole_radius.hpp) costs more cells than the band near its
// triangles. Where it does not fit the device, which refuses before
// anything is allocated, denoise and morph take the band near the
// triangles alone, as before the fans, whose result may stay open.
#pragma once

#include <string>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"

namespace lbmshape {

// `build(true)`, the band with the fans; `build(false)` where that throws
// DeviceError, saying so with `whose` naming the input ("the input's",
// "the meshes'").
template <class Build>
auto withFansWhereTheyFit(const Build& build, const std::string& whose)
{
  try {
    return build(true);
  } catch (const DeviceError& e) {
    log::verbose("the band over " + whose + " holes does not fit (" + e.what() + "): the band near " + whose +
                 " triangles alone");
  }
  return build(false);
}

}  // namespace lbmshape
