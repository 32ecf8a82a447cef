#include "picture_support.hpp"

#include <stdexcept>

#include <stb/stb_image.h>

#include "lbmshape/render/surface_renderer.hpp"

namespace lbmshape::testing {

render::Picture plainPicture(const std::vector<const TriangleMesh*>& meshes, int width, int height, const char* view)
{
  render::Picture p;
  p.width = width, p.height = height;
  p.view = render::parseView(view);
  for (const TriangleMesh* m : meshes) p.panels.push_back({m, {}, ""});
  return p;
}

render::Image draw(gpu::GpuContext& gpu, const render::Picture& picture)
{
  return render::drawSurfaces(gpu, picture, render::arrange(picture));
}

bool covered(const render::Image& image, int x, int y)
{
  const uint8_t* p = image.pixel(x, y);
  return p[0] < 250 || p[1] < 250 || p[2] < 250;
}

long coveredPixels(const render::Image& image, const render::Rect& area)
{
  long n = 0;
  for (int y = area.y; y < area.y + area.height; ++y)
    for (int x = area.x; x < area.x + area.width; ++x) n += covered(image, x, y);
  return n;
}

render::Image readPng(const std::filesystem::path& file)
{
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(file.c_str(), &w, &h, &channels, 4);
  if (!data) throw std::runtime_error("cannot read " + file.string());
  render::Image image(w, h);
  std::copy(data, data + size_t(w) * size_t(h) * 4, image.rgba.begin());
  stbi_image_free(data);
  return image;
}

}  // namespace lbmshape::testing
