// Where things go in a picture: the grid of cells (a mesh each, with a
// label strip under it), the legend strip along the bottom, and the one
// orthographic camera that frames every mesh of the picture at one scale.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/render/picture.hpp"

namespace lbmshape::render {

struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
};

struct Layout {
  int columns = 1, rows = 1;
  std::vector<Rect> meshCells;   // one per panel, row by row
  std::vector<Rect> labelCells;  // under each mesh cell; empty without labels
  std::optional<Rect> legend;
  int textScale = 1;  // of labels and legend (pixels per font pixel)
};

// Columns for n panels: one row up to four, then about twice as many
// columns as rows (a contact sheet on a wide screen); `asked` if not 0.
int columnsFor(int panels, int asked = 0);
// The picture's size when none is given: cells of 512 pixels for one or two
// meshes, 384 up to eight, 256 beyond, plus labels and legend.
glm::ivec2 defaultPictureSize(int panels, bool labels, bool legend, int columns = 0);
Layout arrange(const Picture& picture);

// The camera of a picture, projecting the union of the meshes' bounding
// boxes to fill 92 % of a mesh cell in its tighter direction. The GPU draws
// in floats, which keep their precision near 0 but survive neither a mesh
// 1e38 across (overflow) nor one 1e-40 across (denormals, flushed to zero):
// a position is sent as (p - centre) / unit, within the unit ball, and the
// matrices map those coordinates.
struct Framing {
  glm::dvec3 centre{0.0};
  double unit = 1.0;                // the meshes' radius about the centre, in the mesh's units
  glm::mat4 clipFromCentred{1.0f};  // Vulkan clip space: y down, depth 0 nearest
  glm::mat4 viewFromCentred{1.0f};  // the camera's rotation (x right, y up, z towards the viewer)
  double pixelsPerUnit = 1.0;       // in the mesh's units
};
Framing frame(const Picture& picture, const Rect& cell);

}  // namespace lbmshape::render
