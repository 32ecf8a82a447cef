#include "lbmshape/render/png_file.hpp"

#include <algorithm>
#include <cctype>

#include <stb/stb_image_write.h>

#include "lbmshape/core/error.hpp"

namespace lbmshape::render {

void writePng(const Image& image, AtomicFile& file)
{
  // Through the file's own stream: stb's by-name writer would make the file
  // again if the last-resort handler had removed it (AtomicFile::open).
  std::ofstream out = file.open();
  const auto append = [](void* stream, void* data, int size) {
    static_cast<std::ofstream*>(stream)->write(static_cast<const char*>(data), size);
  };
  if (!out || !stbi_write_png_to_func(append, &out, image.width, image.height, 4, image.rgba.data(), image.width * 4) ||
      !out.flush())
    throw OutputError("cannot write " + file.target().string() + ": " + writeFailure());
  out.close();
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
