#include "lbmshape/render/text_overlay.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

#include "lbmshape/core/number_text.hpp"

namespace lbmshape::render {
namespace {

constexpr glm::vec3 kTextColour{0.10f, 0.10f, 0.12f};

// stb_easy_font indexes its tables by character: anything outside
// printable ASCII would read past them.
std::string printable(const std::string& text)
{
  std::string out = text;
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  return out;
}

}  // namespace

int textWidth(const std::string& text, int scale)
{
  std::string s = printable(text);
  return stb_easy_font_width(s.data()) * scale;
}

void drawText(Image& image, int x, int y, const std::string& text, int scale, glm::vec3 colour)
{
  std::string s = printable(text);
  // Each quad is four vertices of 16 bytes; a character has at most a few dozen.
  struct Vertex {
    float x, y, z;
    unsigned char rgba[4];
  };
  std::vector<Vertex> quads(s.size() * 64 + 64);
  const int count =
      stb_easy_font_print(0.0f, 0.0f, s.data(), nullptr, quads.data(), int(quads.size() * sizeof(Vertex)));
  for (int q = 0; q < count; ++q) {
    const Vertex* v = &quads[size_t(q) * 4];
    // Quads are axis-aligned: corners 0 and 2 are opposite.
    const int x0 = x + int(std::min(v[0].x, v[2].x)) * scale, x1 = x + int(std::max(v[0].x, v[2].x)) * scale;
    const int y0 = y + int(std::min(v[0].y, v[2].y)) * scale, y1 = y + int(std::max(v[0].y, v[2].y)) * scale;
    image.fill(x0, y0, x1, y1, colour);
  }
}

void drawLabel(Image& image, const Rect& cell, const std::string& text, int scale)
{
  std::string shown = text;
  while (shown.size() > 4 && textWidth(shown, scale) > cell.width - 4 * scale) shown = "..." + shown.substr(4);
  const int x = cell.x + (cell.width - textWidth(shown, scale)) / 2;
  drawText(image, x, cell.y + 3 * scale, shown, scale, kTextColour);
}

void drawLegend(Image& image, const Rect& area, const Legend& legend, int scale)
{
  const int line = 12 * scale;
  const int barLeft = area.x + area.width / 5, barRight = area.x + area.width * 4 / 5;
  const int barTop = area.y + line + 2 * scale, barBottom = barTop + line - 2 * scale;
  drawText(image, barLeft, area.y + 2 * scale, legend.title, scale, kTextColour);
  for (int x = barLeft; x < barRight; ++x) {
    const double t = double(x - barLeft) / std::max(barRight - barLeft - 1, 1);
    image.fill(x, barTop, x + 1, barBottom, legendColour(legend, legend.low + t * (legend.high - legend.low)));
  }
  const double middle = 0.5 * (legend.low + legend.high);
  const std::string low = threeSignificantDigits(legend.low), mid = threeSignificantDigits(middle),
                    high = threeSignificantDigits(legend.high);
  const int textTop = barBottom + 2 * scale;
  drawText(image, barLeft, textTop, low, scale, kTextColour);
  drawText(image, (barLeft + barRight - textWidth(mid, scale)) / 2, textTop, mid, scale, kTextColour);
  drawText(image, barRight - textWidth(high, scale), textTop, high, scale, kTextColour);
}

}  // namespace lbmshape::render
