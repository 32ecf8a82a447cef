#include "lbmshape/render/layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lbmshape/core/parameter_bounds.hpp"

namespace lbmshape::render {
namespace {

// Font pixels of stb_easy_font's line, and the strips built on it.
constexpr int kLineHeight = 12;
int labelStrip(int scale) { return kLineHeight * scale + 6 * scale; }
int legendStrip(int scale) { return 3 * kLineHeight * scale + 8 * scale; }
// Text a person reads at the picture's size: one font pixel per screen pixel
// up to about 750 pixels across, then two, up to four; and no larger than
// lets a label of about 25 characters fit its cell.
int textScaleFor(int width, int columns)
{
  return std::clamp(int(std::lround(std::min(width / 500.0, width / columns / 180.0))), 1, 4);
}

}  // namespace

int columnsFor(int panels, int asked)
{
  if (asked > 0) return std::min(asked, std::max(panels, 1));
  if (panels <= 4) return std::max(panels, 1);
  return int(std::ceil(std::sqrt(2.0 * panels)));
}

glm::ivec2 defaultPictureSize(int panels, bool labels, bool legend, int asked)
{
  namespace bounds = parameter_bounds;
  const int columns = columnsFor(panels, asked), rows = (panels + columns - 1) / columns;
  const auto size = [&](int cell) {
    const int width = columns * cell, scale = textScaleFor(width, columns);
    return glm::ivec2(width, rows * (cell + (labels ? labelStrip(scale) : 0)) + (legend ? legendStrip(scale) : 0));
  };
  // Smaller cells where many meshes would make a picture beyond the bounds.
  int cell = panels <= 2 ? 512 : panels <= 8 ? 384 : 256;
  for (glm::ivec2 s = size(cell); cell > 32 && (s.x > bounds::maxPictureSide || s.y > bounds::maxPictureSide ||
                                                long(s.x) * long(s.y) > bounds::maxPicturePixels);
       s = size(cell))
    cell -= 16;
  return size(cell);
}

Layout arrange(const Picture& picture)
{
  Layout layout;
  const int n = std::max<int>(int(picture.panels.size()), 1);
  layout.columns = columnsFor(n, picture.columns);
  layout.rows = (n + layout.columns - 1) / layout.columns;
  layout.textScale = textScaleFor(picture.width, layout.columns);
  const int legendHeight = picture.legend ? std::min(legendStrip(layout.textScale), picture.height / 3) : 0;
  if (picture.legend) layout.legend = Rect{0, picture.height - legendHeight, picture.width, legendHeight};
  const int cellWidth = picture.width / layout.columns;
  const int rowHeight = (picture.height - legendHeight) / layout.rows;
  const int labelHeight = picture.labels ? std::min(labelStrip(layout.textScale), rowHeight / 3) : 0;
  for (int i = 0; i < int(picture.panels.size()); ++i) {
    const int column = i % layout.columns, row = i / layout.columns;
    const Rect cell{column * cellWidth, row * rowHeight, cellWidth, rowHeight - labelHeight};
    layout.meshCells.push_back(cell);
    if (picture.labels) layout.labelCells.push_back({cell.x, cell.y + cell.height, cellWidth, labelHeight});
  }
  return layout;
}

Framing frame(const Picture& picture, const Rect& cell)
{
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
  for (const Panel& panel : picture.panels)
    if (panel.mesh && !panel.mesh->triangles.empty()) {
      const Bounds b = bounds(*panel.mesh);
      lo = glm::min(lo, b.min), hi = glm::max(hi, b.max);
    }
  if (lo.x > hi.x) lo = hi = glm::dvec3(0.0);
  Framing framing;
  framing.centre = 0.5 * (lo + hi);
  const CameraAxes axes = cameraAxes(picture.view);
  // Half extents of the box's projection, and its radius for the depth range.
  const glm::dvec3 half = 0.5 * (hi - lo);
  const auto reach = [&](const glm::dvec3& axis) { return glm::dot(half, glm::abs(axis)); };
  const double radius = std::max(glm::length(half), 1e-300) * 1.01;
  // A flat mesh seen edge-on is a line: its thickness no less than a
  // millionth of its size, so the scale stays finite.
  const double halfWidth = std::max(reach(axes.right), 1e-6 * radius);
  const double halfHeight = std::max(reach(axes.up), 1e-6 * radius);
  framing.unit = radius;
  framing.pixelsPerUnit = 0.92 * std::min(cell.width / (2.0 * halfWidth), cell.height / (2.0 * halfHeight));
  // Clip space from the unit-ball coordinates the vertices are sent in.
  const double sx = 2.0 * framing.pixelsPerUnit * radius / cell.width;
  const double sy = -2.0 * framing.pixelsPerUnit * radius / cell.height;
  // Rows are glm's columns: clip = M * (p, 1).
  glm::dmat4 clip(0.0), view(0.0);
  for (int k = 0; k < 3; ++k) {
    clip[k][0] = sx * axes.right[k];
    clip[k][1] = sy * axes.up[k];
    clip[k][2] = -0.5 * axes.towardsViewer[k];
    view[k][0] = axes.right[k];
    view[k][1] = axes.up[k];
    view[k][2] = axes.towardsViewer[k];
  }
  clip[3] = glm::dvec4(0.0, 0.0, 0.5, 1.0);
  view[3][3] = 1.0;
  framing.clipFromCentred = glm::mat4(clip);
  framing.viewFromCentred = glm::mat4(view);
  return framing;
}

}  // namespace lbmshape::render
