#include "lbmshape/mesh/gltf_json_check.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "lbmshape/core/checked_arithmetic.hpp"
#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {
namespace {

// What tinygltf and nlohmann build per JSON value, at most: a container
// (object or array: a glTF node, a tinygltf::Value map) and a scalar.
constexpr uint64_t bytesPerContainer = 512, bytesPerScalar = 160;
uint64_t structureBudget(uint64_t jsonBytes) { return std::max<uint64_t>(uint64_t(256) << 20, 8 * jsonBytes); }

// The elements of the top-level arrays this pass looks into, with the
// numbers and strings they hold directly.
struct Element {
  std::map<std::string, uint64_t> numbers;
  std::map<std::string, std::string> strings;
  std::set<std::string> negative;  // keys with a negative number
};

class GltfJsonScan : public nlohmann::json_sax<nlohmann::json> {
public:
  std::map<std::string, std::vector<Element>> arrays{{"buffers", {}}, {"bufferViews", {}}, {"images", {}}};
  bool tooDeep = false;
  uint64_t containers = 0, scalars = 0;
  std::string syntaxError;

  bool null() override { return scalar(); }
  bool boolean(bool) override { return scalar(); }
  bool number_integer(number_integer_t n) override
  {
    if (Element* e = element()) n >= 0 ? void(e->numbers[key_] = uint64_t(n)) : void(e->negative.insert(key_));
    return scalar();
  }
  bool number_unsigned(number_unsigned_t n) override
  {
    if (Element* e = element()) e->numbers[key_] = n;
    return scalar();
  }
  bool number_float(number_float_t, const string_t&) override { return scalar(); }
  bool string(string_t& s) override
  {
    if (Element* e = element()) e->strings[key_] = s;
    return scalar();
  }
  bool binary(binary_t&) override { return scalar(); }
  bool key(string_t& k) override
  {
    key_ = k;
    return true;
  }
  bool start_object(std::size_t) override { return open(false); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override
  {
    syntaxError = e.what();
    return false;
  }

private:
  struct Container {
    bool array;
    std::string key;  // the key under which it was opened, in its parent object
  };

  // The element being read when a value sits directly in an object that is
  // an element of one of the top-level arrays looked into.
  Element* element()
  {
    if (stack_.size() != 3 || stack_[2].array || !stack_[1].array) return nullptr;
    auto found = arrays.find(stack_[1].key);
    return found == arrays.end() || found->second.empty() ? nullptr : &found->second.back();
  }
  bool scalar()
  {
    ++scalars;
    key_.clear();
    return true;
  }
  bool open(bool array)
  {
    ++containers;
    if (stack_.size() >= size_t(maxGltfJsonDepth)) {
      tooDeep = true;
      return false;
    }
    const std::string parentKey = stack_.size() == 1 && !stack_[0].array ? key_ : std::string();
    stack_.push_back({array, parentKey});
    if (stack_.size() == 3 && !array && stack_[1].array) {
      auto found = arrays.find(stack_[1].key);
      if (found != arrays.end()) found->second.emplace_back();
    }
    key_.clear();
    return true;
  }
  bool close()
  {
    stack_.pop_back();
    key_.clear();
    return true;
  }

  std::vector<Container> stack_;
  std::string key_;
};

std::optional<uint64_t> number(const Element& e, const std::string& key)
{
  auto found = e.numbers.find(key);
  return found == e.numbers.end() ? std::nullopt : std::optional<uint64_t>(found->second);
}

void checkBuffers(const std::vector<Element>& buffers, bool glb, const MeshSource& source)
{
  std::set<std::string> files;
  for (size_t b = 0; b < buffers.size(); ++b) {
    const std::string name = "buffer " + std::to_string(b);
    const auto length = number(buffers[b], "byteLength");
    if (!length || *length == 0) source.refuse(name + " has no byteLength of at least 1");
    auto uri = buffers[b].strings.find("uri");
    if (uri == buffers[b].strings.end()) {
      // GLB: only buffer 0 may be the binary chunk (glTF 2.0, 4.4.3.3).
      if (glb && b != 0) source.refuse(name + " has no uri, but only buffer 0 may refer to the GLB's binary chunk");
      if (!glb) source.refuse(name + " has no uri");
      continue;
    }
    if (!uri->second.starts_with("data:") && !files.insert(uri->second).second)
      source.refuse(name + " names the file " + text::quoted(uri->second) + " that another buffer already names");
  }
}

// tinygltf hands an image's buffer view to the image loader without
// checking that the view lies in its buffer.
void checkImageViews(const GltfJsonScan& scan, const MeshSource& source)
{
  const std::vector<Element>& views = scan.arrays.at("bufferViews");
  const std::vector<Element>& buffers = scan.arrays.at("buffers");
  const std::vector<Element>& images = scan.arrays.at("images");
  for (size_t i = 0; i < images.size(); ++i) {
    const auto view = number(images[i], "bufferView");
    if (!view) continue;
    const std::string name = "image " + std::to_string(i);
    if (*view >= views.size())
      source.refuse(name + " refers to buffer view " + std::to_string(*view) + ", which does not exist");
    const Element& v = views[*view];
    const auto buffer = number(v, "buffer"), length = number(v, "byteLength");
    const uint64_t offset = number(v, "byteOffset").value_or(0);
    if (!buffer || *buffer >= buffers.size() || !length || v.negative.count("byteOffset"))
      source.refuse(name + "'s buffer view " + std::to_string(*view) + " does not name a buffer and a length");
    const auto end = checkedAdd(offset, *length);
    if (!end || *end > number(buffers[*buffer], "byteLength").value_or(0))
      source.refuse(name + "'s buffer view " + std::to_string(*view) + " reaches past the end of its buffer");
  }
}

}  // namespace

std::vector<GltfBufferEntry> checkGltfJson(std::string_view json, bool glb, const MeshSource& source)
{
  GltfJsonScan scan;
  nlohmann::json::sax_parse(json.begin(), json.end(), &scan, nlohmann::json::input_format_t::json);
  if (scan.tooDeep)
    source.refuse("its JSON nests more than " + std::to_string(maxGltfJsonDepth) +
                  " levels deep, far beyond any glTF file's structure");
  if (!scan.syntaxError.empty()) source.refuse("its JSON is malformed (" + text::printable(scan.syntaxError) + ")");
  if (scan.containers * bytesPerContainer + scan.scalars * bytesPerScalar > structureBudget(json.size()))
    source.refuse("its JSON holds " + std::to_string(scan.containers + scan.scalars) +
                  " values, more than a glTF file of this size needs");
  checkBuffers(scan.arrays.at("buffers"), glb, source);
  checkImageViews(scan, source);

  std::vector<GltfBufferEntry> buffers;
  for (const Element& b : scan.arrays.at("buffers")) {
    auto uri = b.strings.find("uri");
    buffers.push_back({uri == b.strings.end() ? std::string() : uri->second, number(b, "byteLength").value_or(0)});
  }
  return buffers;
}

}  // namespace lbmshape
