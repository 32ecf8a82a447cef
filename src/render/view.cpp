#include "lbmshape/render/view.hpp"

#include <cmath>
#include <cstdlib>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"

namespace lbmshape::render {

View parseView(const std::string& text)
{
  if (text == "front") return {0.0, 0.0};
  if (text == "side") return {90.0, 0.0};
  if (text == "top") return {0.0, 90.0};
  if (text == "iso") return {45.0, std::atan(1.0 / std::sqrt(2.0)) * 180.0 / M_PI};
  const std::string expected =
      nameOf(Parameter::View) + " '" + text + "' is not front, side, top, iso or AZ,EL in degrees (for example 30,20)";
  const size_t comma = text.find(',');
  if (comma == std::string::npos) throw UsageError(expected);
  const std::string azimuth = text.substr(0, comma), elevation = text.substr(comma + 1);
  char* end = nullptr;
  View view;
  view.azimuthDegrees = std::strtod(azimuth.c_str(), &end);
  if (azimuth.empty() || *end != '\0' || !std::isfinite(view.azimuthDegrees)) throw UsageError(expected);
  view.elevationDegrees = std::strtod(elevation.c_str(), &end);
  if (elevation.empty() || *end != '\0' || !std::isfinite(view.elevationDegrees)) throw UsageError(expected);
  if (std::abs(view.elevationDegrees) > 90.0)
    throw UsageError(nameOf(Parameter::View) + " elevation " + elevation + " is outside [-90, 90] degrees");
  return view;
}

CameraAxes cameraAxes(const View& view)
{
  const double az = view.azimuthDegrees * M_PI / 180.0, el = view.elevationDegrees * M_PI / 180.0;
  CameraAxes axes;
  axes.towardsViewer = {std::sin(az) * std::cos(el), std::sin(el), std::cos(az) * std::cos(el)};
  axes.right = {std::cos(az), 0.0, -std::sin(az)};
  axes.up = glm::cross(axes.towardsViewer, axes.right);
  return axes;
}

}  // namespace lbmshape::render
