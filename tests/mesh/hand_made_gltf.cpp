#include "mesh/hand_made_gltf.hpp"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>

namespace lbmshape::testing::meshio {

HandMadeGltf::HandMadeGltf()
{
  json = {{"asset", {{"version", "2.0"}}},          {"buffers", nlohmann::json::array()},
          {"bufferViews", nlohmann::json::array()}, {"accessors", nlohmann::json::array()},
          {"meshes", nlohmann::json::array()},      {"nodes", nlohmann::json::array()}};
}

int HandMadeGltf::addView(const void* data, size_t bytes, int target)
{
  buffer_.resize((buffer_.size() + 3) / 4 * 4, 0);
  json["bufferViews"].push_back(
      {{"buffer", 0}, {"byteOffset", buffer_.size()}, {"byteLength", bytes}, {"target", target}});
  const auto* p = static_cast<const unsigned char*>(data);
  buffer_.insert(buffer_.end(), p, p + bytes);
  return int(json["bufferViews"].size() - 1);
}

int HandMadeGltf::addPositions(const std::vector<glm::vec3>& positions)
{
  glm::vec3 lo(positions.front()), hi(positions.front());
  for (const auto& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const int view = addView(positions.data(), positions.size() * sizeof(glm::vec3), 34962);
  json["accessors"].push_back({{"bufferView", view},
                               {"componentType", 5126},
                               {"count", positions.size()},
                               {"type", "VEC3"},
                               {"min", {lo.x, lo.y, lo.z}},
                               {"max", {hi.x, hi.y, hi.z}}});
  return int(json["accessors"].size() - 1);
}

int HandMadeGltf::addIndices(const std::vector<uint32_t>& indices)
{
  const int view = addView(indices.data(), indices.size() * 4, 34963);
  json["accessors"].push_back(
      {{"bufferView", view}, {"componentType", 5125}, {"count", indices.size()}, {"type", "SCALAR"}});
  return int(json["accessors"].size() - 1);
}

int HandMadeGltf::addIndices16(const std::vector<uint16_t>& indices)
{
  const int view = addView(indices.data(), indices.size() * 2, 34963);
  json["accessors"].push_back(
      {{"bufferView", view}, {"componentType", 5123}, {"count", indices.size()}, {"type", "SCALAR"}});
  return int(json["accessors"].size() - 1);
}

int HandMadeGltf::addColours(const std::vector<glm::vec3>& colours)
{
  const int view = addView(colours.data(), colours.size() * sizeof(glm::vec3), 34962);
  json["accessors"].push_back(
      {{"bufferView", view}, {"componentType", 5126}, {"count", colours.size()}, {"type", "VEC3"}});
  return int(json["accessors"].size() - 1);
}

int HandMadeGltf::addColours8(const std::vector<glm::u8vec4>& colours)
{
  const int view = addView(colours.data(), colours.size() * 4, 34962);
  json["accessors"].push_back({{"bufferView", view},
                               {"componentType", 5121},
                               {"normalized", true},
                               {"count", colours.size()},
                               {"type", "VEC4"}});
  return int(json["accessors"].size() - 1);
}

int HandMadeGltf::addJoints(const std::vector<glm::u8vec4>& joints)
{
  const int view = addView(joints.data(), joints.size() * 4, 34962);
  json["accessors"].push_back(
      {{"bufferView", view}, {"componentType", 5121}, {"count", joints.size()}, {"type", "VEC4"}});
  return int(json["accessors"].size() - 1);
}

int HandMadeGltf::addWeights(const std::vector<glm::vec4>& weights)
{
  const int view = addView(weights.data(), weights.size() * sizeof(glm::vec4), 34962);
  json["accessors"].push_back(
      {{"bufferView", view}, {"componentType", 5126}, {"count", weights.size()}, {"type", "VEC4"}});
  return int(json["accessors"].size() - 1);
}

int HandMadeGltf::addMatrices(const std::vector<glm::mat4>& matrices)
{
  const int view = addView(matrices.data(), matrices.size() * sizeof(glm::mat4), -1);
  json["bufferViews"].back().erase("target");
  json["accessors"].push_back(
      {{"bufferView", view}, {"componentType", 5126}, {"count", matrices.size()}, {"type", "MAT4"}});
  return int(json["accessors"].size() - 1);
}

int HandMadeGltf::addMesh(int positions, int indices, int mode)
{
  nlohmann::json primitive = {{"attributes", {{"POSITION", positions}}}, {"mode", mode}};
  if (indices >= 0) primitive["indices"] = indices;
  json["meshes"].push_back({{"primitives", {primitive}}});
  return int(json["meshes"].size() - 1);
}

void HandMadeGltf::writeGltf(const std::filesystem::path& path) const
{
  std::filesystem::path bin = path;
  bin.replace_extension(".bin");
  nlohmann::json out = json;
  out["buffers"] = {{{"byteLength", buffer_.size()}, {"uri", bin.filename().string()}}};
  std::ofstream(path) << out.dump(2);
  std::ofstream(bin, std::ios::binary)
      .write(reinterpret_cast<const char*>(buffer_.data()), std::streamsize(buffer_.size()));
}

void HandMadeGltf::writeGlb(const std::filesystem::path& path) const
{
  nlohmann::json out = json;
  out["buffers"] = {{{"byteLength", buffer_.size()}}};
  std::string text = out.dump();
  text.resize((text.size() + 3) / 4 * 4, ' ');
  std::vector<unsigned char> binary = buffer_;
  binary.resize((binary.size() + 3) / 4 * 4, 0);
  std::vector<uint32_t> header = {0x46546C67u, 2u, uint32_t(12 + 8 + text.size() + 8 + binary.size())};
  std::ofstream file(path, std::ios::binary);
  auto put32 = [&](uint32_t v) { file.write(reinterpret_cast<const char*>(&v), 4); };
  for (uint32_t v : header) put32(v);
  put32(uint32_t(text.size()));
  put32(0x4E4F534Au);  // "JSON"
  file.write(text.data(), std::streamsize(text.size()));
  put32(uint32_t(binary.size()));
  put32(0x004E4942u);  // "BIN\0"
  file.write(reinterpret_cast<const char*>(binary.data()), std::streamsize(binary.size()));
}

std::vector<float> GlbContent::floats(int index) const
{
  const auto& accessor = json.at("accessors").at(size_t(index));
  const auto& view = json.at("bufferViews").at(accessor.at("bufferView").get<size_t>());
  const std::map<std::string, size_t> components = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}};
  const size_t count = accessor.at("count").get<size_t>() * components.at(accessor.at("type").get<std::string>());
  const size_t offset = view.value("byteOffset", size_t(0)) + accessor.value("byteOffset", size_t(0));
  if (offset + count * 4 > binary.size()) throw std::runtime_error("accessor beyond the binary chunk");
  std::vector<float> values(count);
  std::memcpy(values.data(), binary.data() + offset, count * 4);
  return values;
}

GlbContent readGlb(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  auto get32 = [&](size_t at) {
    if (at + 4 > bytes.size()) throw std::runtime_error(path.string() + " is cut short");
    uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
  };
  GlbContent content;
  if (bytes.size() < 20 || get32(0) != 0x46546C67u) throw std::runtime_error(path.string() + " is not a GLB file");
  const uint32_t jsonLength = get32(12);
  content.json = nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + jsonLength);
  const size_t binAt = 20 + jsonLength;
  if (binAt + 8 <= bytes.size()) {
    const uint32_t binLength = get32(binAt);
    content.binary.assign(bytes.begin() + long(binAt + 8), bytes.begin() + long(binAt + 8 + binLength));
  }
  return content;
}

}  // namespace lbmshape::testing::meshio
