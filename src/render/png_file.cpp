#include "render/png_file.hpp"

#include <algorithm>
#include <cctype>

#include <stb/stb_image_write.h>

#include "core/error.hpp"

namespace lbmshape::render {

void writePng(const Image& image, AtomicFile& file)
{
  if (!stbi_write_png(file.temporaryPath().c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4))
    throw OutputError("cannot write " + file.target().string() + " (is the disk full?)");
  file.commit();
}

void requirePngPath(const std::filesystem::path& path, const std::string& what)
{
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (extension != ".png") throw UsageError(what + " " + path.string() + " must be a .png file");
}

}  // namespace lbmshape::render
