#include "lbmshape/mesh/glb_container.hpp"

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

std::string glbHead(std::string json, size_t binaryBytes)
{
  json.resize(glbPadded(json.size()), ' ');
  const size_t binaryChunk = glbPadded(binaryBytes);
  const size_t total = 12 + 8 + json.size() + (binaryBytes == 0 ? 0 : 8 + binaryChunk);
  std::string out;
  out.reserve(28 + json.size());
  appendWord(out, 0x46546C67);  // "glTF"
  appendWord(out, 2);
  appendWord(out, uint32_t(total));
  appendWord(out, uint32_t(json.size()));
  appendWord(out, 0x4E4F534A);  // "JSON"
  out += json;
  if (binaryBytes != 0) {
    appendWord(out, uint32_t(binaryChunk));
    appendWord(out, 0x004E4942);  // "BIN\0"
  }
  return out;
}

std::string glbFile(std::string json, std::string binary)
{
  std::string out = glbHead(std::move(json), binary.size());
  out.reserve(out.size() + binary.size() + 3);
  out += binary;
  out.append(glbPadded(binary.size()) - binary.size(), '\0');
  return out;
}

void writeGlb(std::ostream& out, std::string json, std::string_view binary)
{
  out << glbHead(std::move(json), binary.size());
  out.write(binary.data(), std::streamsize(binary.size()));
  out.write("\0\0\0", std::streamsize(glbPadded(binary.size()) - binary.size()));
}

}  // namespace lbmshape
