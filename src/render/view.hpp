// Where the camera looks from: an azimuth about the mesh's +Y axis (0 looks
// from +Z, 90 from +X) and an elevation above the XZ plane (90 looks down
// from +Y). The camera is orthographic, so a picture's scale is the same
// everywhere in it, and side-by-side meshes compare by size.
#pragma once

#include <string>

#include <glm/glm.hpp>

namespace lbmshape::render {

struct View {
  double azimuthDegrees = 0.0;
  double elevationDegrees = 0.0;
};

// front (0, 0), side (90, 0), top (0, 90), iso (45, 35.26), or "AZ,EL" in
// degrees (elevation within [-90, 90]). UsageError naming --view otherwise.
View parseView(const std::string& text);

// The camera's axes in the mesh's coordinates: right and up span the
// picture, towardsViewer points from the mesh to the eye. Right stays in the
// XZ plane, so the picture never rolls, straight down included.
struct CameraAxes {
  glm::dvec3 right, up, towardsViewer;
};
CameraAxes cameraAxes(const View& view);

}  // namespace lbmshape::render
