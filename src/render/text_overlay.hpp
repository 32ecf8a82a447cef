// Text on a picture, drawn on the CPU after the device has drawn the
// meshes: labels under the meshes and the colour legend. The font is
// stb_easy_font's (printable ASCII, 7 font pixels high), scaled by whole
// pixels so it stays crisp.
#pragma once

#include <string>

#include "lbmshape/render/colour_map.hpp"
#include "lbmshape/render/image.hpp"
#include "lbmshape/render/layout.hpp"

namespace lbmshape::render {

// Width in pixels of `text` at `scale`.
int textWidth(const std::string& text, int scale);
// `text` with its top left corner at (x, y); characters outside printable
// ASCII show as '?'. Clipped to the picture.
void drawText(Image& image, int x, int y, const std::string& text, int scale, glm::vec3 colour);
// `text` centred in `cell`, shortened from the left ("...tail") to fit.
void drawLabel(Image& image, const Rect& cell, const std::string& text, int scale);
// The legend's colour bar across the middle of `area`, its title above and
// its low, middle and high values below.
void drawLegend(Image& image, const Rect& area, const Legend& legend, int scale);

}  // namespace lbmshape::render
