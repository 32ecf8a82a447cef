#include "lbmshape/mesh/gltf_meshopt_decoding.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include "lbmshape/mesh/glb_container.hpp"
#include "lbmshape/mesh/gltf_compression.hpp"

namespace lbmshape {
namespace {

// Deeper JSON than any glTF file needs; refused before it is built.
constexpr int kDepthLimit = 64;
// A JSON chunk larger than any compressed GLB needs (a morph of thousands of
// frames has a few MiB).
constexpr size_t kJsonLimit = size_t(64) << 20;

uint64_t unsignedField(const MeshSource& source, const nlohmann::json& object, const char* key, const std::string& what,
                       std::optional<uint64_t> otherwise = std::nullopt)
{
  const auto found = object.find(key);
  if (found == object.end()) {
    if (otherwise) return *otherwise;
    source.refuse(what + " has no " + key);
  }
  if (!found->is_number_unsigned()) source.refuse(what + "'s " + key + " is not a whole number of at least 0");
  return found->get<uint64_t>();
}

// Decodes one buffer view's data into `out`, as its extension object says.
void decodeView(const MeshSource& source, const nlohmann::json& ext, std::string_view binary, size_t index,
                uint64_t& budget, std::string& out, uint64_t& offset, uint64_t& length)
{
  const std::string what = "buffer view " + std::to_string(index) + "'s " + meshoptExtension;
  if (!ext.is_object()) source.refuse(what + " is not an object");
  if (unsignedField(source, ext, "buffer", what) != 0)
    source.refuse(what + " reads from a buffer other than the GLB's binary chunk, which lbmshape does not read");
  const uint64_t from = unsignedField(source, ext, "byteOffset", what, 0),
                 size = unsignedField(source, ext, "byteLength", what);
  const uint64_t stride = unsignedField(source, ext, "byteStride", what),
                 count = unsignedField(source, ext, "count", what);
  if (from > binary.size() || size > binary.size() - from) source.refuse(what + " reaches past the binary chunk");
  const auto modeField = ext.find("mode");
  if (modeField == ext.end() || !modeField->is_string()) source.refuse(what + " has no mode");
  const auto filterField = ext.find("filter");
  if (filterField != ext.end() && !filterField->is_string()) source.refuse(what + "'s filter is not a name");
  const std::string mode = *modeField, filter = filterField == ext.end() ? "NONE" : filterField->get<std::string>();
  const bool attributes = mode == "ATTRIBUTES", triangles = mode == "TRIANGLES", indices = mode == "INDICES";
  if (!attributes && !triangles && !indices) source.refuse(what + " has the unknown mode " + mode.substr(0, 40));
  if (attributes ? (stride == 0 || stride % 4 != 0 || stride > 256) : (stride != 2 && stride != 4))
    source.refuse(what + " has a byteStride of " + std::to_string(stride) + ", which its mode does not allow");
  if (triangles && count % 3 != 0)
    source.refuse(what + " holds " + std::to_string(count) + " indices, not whole triangles");
  if (count > budget / stride) source.refuse(what + " would decode to more bytes than a file of this size can hold");
  budget -= count * stride;

  out.resize((out.size() + 3) / 4 * 4, '\0');
  offset = out.size();
  length = count * stride;
  out.resize(out.size() + length);
  auto* target = reinterpret_cast<unsigned char*>(out.data() + offset);
  const auto* encoded = reinterpret_cast<const unsigned char*>(binary.data() + from);
  const int status = attributes  ? meshopt_decodeVertexBuffer(target, count, stride, encoded, size)
                     : triangles ? meshopt_decodeIndexBuffer(target, count, stride, encoded, size)
                                 : meshopt_decodeIndexSequence(target, count, stride, encoded, size);
  if (status != 0) source.refuse(what + ": the compressed data is malformed");
  if (filter == "NONE") return;
  if (!attributes) source.refuse(what + " has a filter, which only attributes may have");
  if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8))
    meshopt_decodeFilterOct(target, count, stride);
  else if (filter == "QUATERNION" && stride == 8)
    meshopt_decodeFilterQuat(target, count, stride);
  else if (filter == "EXPONENTIAL")
    meshopt_decodeFilterExp(target, count, stride);
  else
    source.refuse(what + " has the filter " + filter.substr(0, 40) + " with a byteStride of " + std::to_string(stride) +
                  ", which meshoptimizer does not define");
}

}  // namespace

std::optional<std::string> decodeMeshoptGlb(const MeshSource& source, std::string_view jsonText,
                                            std::string_view binary)
{
  if (jsonText.find(meshoptExtension) == std::string_view::npos) return std::nullopt;
  // The JSON is parsed whole here, before the reader's own checks: a tree
  // takes many times its text, so the text is bounded first.
  if (jsonText.size() > kJsonLimit)
    source.refuse("its JSON chunk of " + std::to_string(jsonText.size() >> 20) + " MiB is larger than the " +
                  std::to_string(kJsonLimit >> 20) + " MiB lbmshape reads beside EXT_meshopt_compression");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(jsonText, [](int depth, nlohmann::json::parse_event_t, nlohmann::json&) {
      if (depth > kDepthLimit) throw std::length_error("nested too deeply");
      return true;
    });
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    source.refuse("its JSON is not readable (" + std::string(e.what()).substr(0, 120) + ")");
  }
  if (!json.is_object()) source.refuse("its JSON is not an object");
  const auto views = json.find("bufferViews");
  const auto buffers = json.find("buffers");
  if (views == json.end() || !views->is_array() || buffers == json.end() || !buffers->is_array() || buffers->empty() ||
      !buffers->front().is_object())
    return std::nullopt;  // nothing to decode: the reader says what else is wrong

  // Every decoded byte costs memory: at most 128 times the file (all-zero
  // attributes compress about 64 times), and no less than a mebibyte; and
  // the decoded GLB, JSON and all, must stay a GLB (under 4 GiB).
  const uint64_t used = 64 + 2 * uint64_t(jsonText.size()) + binary.size();
  const uint64_t glbRoom = used < UINT32_MAX ? UINT32_MAX - used : 0;
  uint64_t budget = std::min(std::max<uint64_t>(128 * uint64_t(source.bytes.size()), uint64_t(1) << 20), glbRoom);
  std::string decodedBinary(binary);
  size_t decodedViews = 0;
  for (size_t i = 0; i < views->size(); ++i) {
    nlohmann::json& view = (*views)[i];
    if (!view.is_object() || !view.contains("extensions") || !view["extensions"].is_object() ||
        !view["extensions"].contains(meshoptExtension))
      continue;
    uint64_t offset = 0, length = 0;
    decodeView(source, view["extensions"][meshoptExtension], binary, i, budget, decodedBinary, offset, length);
    view["buffer"] = 0;
    view["byteOffset"] = offset;
    view["byteLength"] = length;
    view["extensions"].erase(meshoptExtension);
    ++decodedViews;
  }
  if (decodedViews == 0) return std::nullopt;
  // Fallback buffers held what a decoder makes: no view reads them now.
  for (nlohmann::json& buffer : *buffers)
    if (buffer.is_object() && buffer.contains("extensions") && buffer["extensions"].is_object() &&
        buffer["extensions"].contains(meshoptExtension)) {
      buffer = {{"byteLength", 4}, {"uri", "data:application/octet-stream;base64,AAAAAA=="}};
    }
  decodedBinary.resize(glbPadded(decodedBinary.size()), '\0');
  (*buffers)[0]["byteLength"] = decodedBinary.size();
  for (const char* list : {"extensionsUsed", "extensionsRequired"})
    if (json.contains(list) && json[list].is_array()) {
      auto& names = json[list];
      names.erase(std::remove(names.begin(), names.end(), nlohmann::json(meshoptExtension)), names.end());
    }

  return glbFile(json.dump(), std::move(decodedBinary));
}

}  // namespace lbmshape
