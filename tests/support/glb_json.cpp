#include "support/glb_json.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace lbmshape::testing {

nlohmann::json glbJson(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  // 12-byte header, then the first chunk (the JSON): length, type, content.
  uint32_t length = 0;
  if (bytes.size() < 20) throw std::runtime_error(path.string() + " is too short to be a .glb file");
  std::memcpy(&length, bytes.data() + 12, 4);
  return nlohmann::json::parse(bytes.substr(20, length));
}

}  // namespace lbmshape::testing
