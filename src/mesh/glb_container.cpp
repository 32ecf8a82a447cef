#include "mesh/glb_container.hpp"

#include <cstring>

namespace lbmshape {
namespace {

void appendWord(std::string& bytes, uint32_t value) { bytes.append(reinterpret_cast<const char*>(&value), 4); }

}  // namespace

uint32_t glbWord(std::string_view bytes, size_t at)
{
  uint32_t value = 0;
  std::memcpy(&value, bytes.data() + at, 4);  // little-endian, as GLB is
  return value;
}

GlbChunks glbChunks(std::string_view glb)
{
  const size_t jsonLength = glbWord(glb, 12), binaryAt = 20 + jsonLength;
  GlbChunks chunks{glb.substr(20, jsonLength), {}};
  if (glb.size() >= binaryAt + 8) chunks.binary = glb.substr(binaryAt + 8, glbWord(glb, binaryAt));
  return chunks;
}

std::string glbFile(std::string json, std::string binary)
{
  json.resize((json.size() + 3) / 4 * 4, ' ');
  binary.resize((binary.size() + 3) / 4 * 4, '\0');
  const size_t total = 12 + 8 + json.size() + (binary.empty() ? 0 : 8 + binary.size());
  std::string out;
  out.reserve(total);
  appendWord(out, 0x46546C67);  // "glTF"
  appendWord(out, 2);
  appendWord(out, uint32_t(total));
  appendWord(out, uint32_t(json.size()));
  appendWord(out, 0x4E4F534A);  // "JSON"
  out += json;
  if (!binary.empty()) {
    appendWord(out, uint32_t(binary.size()));
    appendWord(out, 0x004E4942);  // "BIN\0"
    out += binary;
  }
  return out;
}

}  // namespace lbmshape
