#include "lbmshape/mesh/compressed_file.hpp"

#include <array>
#include <utility>

namespace lbmshape {

std::optional<std::string> compressionOf(std::string_view bytes)
{
  using namespace std::string_view_literals;
  static const std::array<std::pair<std::string_view, const char*>, 6> magics = {{
      {"\x1f\x8b"sv, "gzip"},
      {"PK\x03\x04"sv, "zip"},
      {"BZh"sv, "bzip2"},
      {"\xfd"
       "7zXZ\x00"sv,
       "xz"},
      {"\x28\xb5\x2f\xfd"sv, "zstd"},
      {"7z\xbc\xaf\x27\x1c"sv, "7-zip"},
  }};
  for (const auto& [magic, kind] : magics)
    if (bytes.starts_with(magic)) return kind;
  return std::nullopt;
}

void refuseCompressed(const MeshSource& source)
{
  if (const auto kind = compressionOf(source.bytes))
    source.refuse("it is a " + *kind + "-compressed file; decompress it first");
}

}  // namespace lbmshape
