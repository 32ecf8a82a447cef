#include "lbmshape/mesh/gltf_json_check.hpp"

#include <algorithm>
#include <exception>
#include <map>
#include <optional>
#include <set>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include "lbmshape/core/checked_arithmetic.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/mesh/gltf_json_element.hpp"
#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {
namespace {

// What tinygltf and nlohmann build per JSON value, at most: a container
// (object or array: a glTF node, a tinygltf::Value map) and a scalar.
constexpr uint64_t bytesPerContainer = 512, bytesPerScalar = 160;
uint64_t structureBudget(uint64_t jsonBytes) { return std::max<uint64_t>(uint64_t(256) << 20, 8 * jsonBytes); }

// How a property's value is shown in a message: short, and printable.
std::string shown(const std::string& written)
{
  constexpr size_t longest = 40;
  return written.size() <= longest ? written : written.substr(0, longest) + "...";
}

class GltfJsonScan : public nlohmann::json_sax<nlohmann::json> {
public:
  explicit GltfJsonScan(const MeshSource& source) : source_(source) {}

  std::map<std::string, std::vector<GltfJsonElement>> kept{{"buffers", {}}, {"bufferViews", {}}, {"images", {}}};
  GltfJsonElement top;  // the top-level object's own properties
  // The names in the top level's extensionsRequired and extensionsUsed.
  std::map<std::string, std::vector<std::string>> extensionLists{{"extensionsRequired", {}}, {"extensionsUsed", {}}};
  uint64_t scenes = 0;
  bool tooDeep = false;
  uint64_t containers = 0, scalars = 0;
  std::string syntaxError;
  // The first element's refusal, given once the file's required extensions
  // are judged: a compressed file's elements are no reason to refuse it
  // when the extension it requires is.
  std::exception_ptr refusal;

  bool null() override { return scalar("null", JsonKind::Null); }
  bool boolean(bool b) override { return scalar(b ? "true" : "false", JsonKind::Boolean); }
  bool number_integer(number_integer_t n) override { return scalar(std::to_string(n), JsonKind::Number); }
  bool number_unsigned(number_unsigned_t n) override { return scalar(std::to_string(n), JsonKind::Number, n); }
  // nlohmann refuses a number beyond a double's range: every one read is finite.
  bool number_float(number_float_t, const string_t& written) override
  {
    return scalar(text::printable(shown(written)), JsonKind::Number);
  }
  bool string(string_t& s) override
  {
    if (GltfJsonElement* e = directElement(); e && current_.back().collection == "buffers") e->strings[key_] = s;
    if (stack_.size() == 2 && stack_[1].array && extensionLists.count(stack_[1].key))
      extensionLists[stack_[1].key].push_back(s);
    return scalar(text::quoted(shown(s)), JsonKind::String);
  }
  bool binary(binary_t&) override { return scalar("binary data", JsonKind::String); }
  // JSON leaves a key given twice in one object to the reader; tinygltf
  // (nlohmann) keeps the last, which this pass would not have checked.
  bool key(string_t& k) override
  {
    if (!stack_.empty() && !stack_.back().keys.insert(k).second) {
      const std::string where = !current_.empty() && current_.back().depth == stack_.size()
                                    ? " of " + gltfElementName(current_.back().collection, current_.back().index)
                                    : "";
      defer(
          [&] { source_.refuse("its JSON gives the key " + text::quoted(shown(k)) + " twice in one object" + where); });
    }
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
  template <class Check>
  void defer(Check check)
  {
    if (refusal) return;
    try {
      check();
    } catch (const InputError&) {
      refusal = std::current_exception();
    }
  }

  struct Container {
    bool array;
    std::string key;                         // the key under which it was opened, in its parent object
    uint64_t items = 0;                      // values in it so far
    std::unordered_set<std::string> keys{};  // an object's keys so far
  };
  // An element of a checked collection being read, and the container depth of its object.
  struct OpenElement {
    std::string collection;
    std::vector<uint64_t> index;
    size_t depth;
    GltfJsonElement element;
  };

  // The element whose object holds the value about to be read directly.
  GltfJsonElement* directElement()
  {
    return !current_.empty() && current_.back().depth == stack_.size() ? &current_.back().element : nullptr;
  }
  // The summary of the array, directly in an element, that holds the value about to be read.
  GltfJsonElement::Array* elementArray()
  {
    if (current_.empty() || current_.back().depth + 1 != stack_.size() || !stack_.back().array) return nullptr;
    return &current_.back().element.arrays[stack_.back().key];
  }
  // Notes a value (a scalar, or a container about to open) in what holds it.
  void note(const std::string& written, JsonKind kind, std::optional<uint64_t> whole)
  {
    if (!stack_.empty()) ++stack_.back().items;
    if (GltfJsonElement* e = directElement()) {
      e->kinds[key_] = kind;
      e->written[key_] = written;
      if (whole) e->wholeNumbers[key_] = *whole;
    } else if (GltfJsonElement::Array* a = elementArray()) {
      ++a->count;
      a->allNumbers = a->allNumbers && kind == JsonKind::Number;
      a->allWholeNumbers = a->allWholeNumbers && whole.has_value();
      a->allStrings = a->allStrings && kind == JsonKind::String;
      a->allObjects = a->allObjects && kind == JsonKind::Object;
    }
  }
  bool scalar(const std::string& written, JsonKind kind, std::optional<uint64_t> whole = std::nullopt)
  {
    ++scalars;
    note(written, kind, whole);
    key_.clear();
    return true;
  }
  // The dotted path of keys of the checked element whose object was just
  // opened ("nodes", "meshes.primitives", "accessors.sparse.indices"), and
  // its place in each array on the way; empty where it is none.
  std::pair<std::string, std::vector<uint64_t>> collectionOfNewObject() const
  {
    constexpr size_t deepestChecked = 6;  // root, meshes, a mesh, primitives, a primitive, its targets' one
    if (stack_.size() < 2 || stack_[0].array || stack_.size() > deepestChecked + 1) return {};
    std::string path;
    std::vector<uint64_t> index;
    for (size_t k = 1; k < stack_.size(); ++k) {
      if (stack_[k - 1].array) {
        if (stack_[k].array) return {};  // an array in an array: nothing glTF has
        index.push_back(stack_[k - 1].items - 1);
      } else {
        path += (path.empty() ? "" : ".") + stack_[k].key;
      }
    }
    const bool inAnArray = stack_[stack_.size() - 2].array;
    return isCheckedGltfCollection(path, inAnArray) ? std::pair(path, index)
                                                    : std::pair<std::string, std::vector<uint64_t>>{};
  }
  bool open(bool array)
  {
    ++containers;
    if (stack_.size() >= size_t(maxGltfJsonDepth)) {
      tooDeep = true;
      return false;
    }
    note(array ? "an array" : "an object", array ? JsonKind::Array : JsonKind::Object, std::nullopt);
    const bool inObject = !stack_.empty() && !stack_.back().array;
    stack_.push_back({array, inObject ? key_ : std::string()});
    if (stack_.size() == 1 && !array) {
      current_.push_back({"", {}, 1, {}});
    } else if (!array) {
      auto [collection, index] = collectionOfNewObject();
      if (!collection.empty()) current_.push_back({collection, index, stack_.size(), {}});
    } else if (GltfJsonElement* e = current_.empty() || current_.back().depth + 1 != stack_.size()
                                        ? nullptr
                                        : &current_.back().element) {
      e->arrays[stack_.back().key] = {};  // an array directly in an element: summarized
    }
    key_.clear();
    return true;
  }
  bool close()
  {
    if (!current_.empty() && current_.back().depth == stack_.size()) {
      OpenElement& done = current_.back();
      defer([&] { checkGltfElement(done.collection, done.index, done.element, source_); });
      if (done.collection.empty()) {
        top = std::move(done.element);
      } else {
        if (done.collection == "scenes") ++scenes;
        if (kept.count(done.collection)) kept[done.collection].push_back(std::move(done.element));
      }
      current_.pop_back();
    }
    stack_.pop_back();
    key_.clear();
    return true;
  }

  const MeshSource& source_;
  std::vector<Container> stack_;
  std::vector<OpenElement> current_;
  std::string key_;
};

std::optional<uint64_t> number(const GltfJsonElement& e, const std::string& key)
{
  auto found = e.wholeNumbers.find(key);
  return found == e.wholeNumbers.end() ? std::nullopt : std::optional<uint64_t>(found->second);
}

void checkBuffers(const std::vector<GltfJsonElement>& buffers, bool glb, const std::vector<std::string>& used,
                  const MeshSource& source)
{
  // A meshopt file's fallback buffer has no uri: what it holds is made by
  // decoding, which lbmshape does for GLB files only.
  const std::string meshoptFallback =
      std::find(used.begin(), used.end(), "EXT_meshopt_compression") != used.end()
          ? " (EXT_meshopt_compression's fallback buffer? lbmshape decodes meshopt in GLB files only)"
          : "";
  std::set<std::string> files;
  for (size_t b = 0; b < buffers.size(); ++b) {
    const std::string name = "buffer " + std::to_string(b);
    const auto length = number(buffers[b], "byteLength");
    if (!length || *length == 0) source.refuse(name + " has no byteLength of at least 1");
    auto uri = buffers[b].strings.find("uri");
    if (uri == buffers[b].strings.end()) {
      // GLB: only buffer 0 may be the binary chunk (glTF 2.0, 4.4.3.3).
      if (glb && b != 0) source.refuse(name + " has no uri, but only buffer 0 may refer to the GLB's binary chunk");
      if (!glb) source.refuse(name + " has no uri" + meshoptFallback);
      continue;
    }
    if (!uri->second.starts_with("data:") && !files.insert(uri->second).second)
      source.refuse(name + " names the file " + text::quotedName(uri->second) + " that another buffer already names");
  }
}

// tinygltf reads a "scene" that is no scene's index as absent, and lbmshape
// showed scene 0 in its place. (Its type is checked with the top level's
// other properties, gltf_json_element.cpp.)
void checkDefaultScene(const GltfJsonScan& scan, const MeshSource& source)
{
  const auto scene = number(scan.top, "scene");
  if (scene && *scene >= scan.scenes)
    source.refuse("its default scene is scene " + std::to_string(*scene) + ", but it has " +
                  std::to_string(scan.scenes) + (scan.scenes == 1 ? " scene" : " scenes"));
}

// tinygltf hands an image's buffer view to the image loader without
// checking that the view lies in its buffer.
void checkImageViews(const GltfJsonScan& scan, const MeshSource& source)
{
  const std::vector<GltfJsonElement>& views = scan.kept.at("bufferViews");
  const std::vector<GltfJsonElement>& buffers = scan.kept.at("buffers");
  const std::vector<GltfJsonElement>& images = scan.kept.at("images");
  for (size_t i = 0; i < images.size(); ++i) {
    const auto view = number(images[i], "bufferView");
    if (!view) continue;
    const std::string name = "image " + std::to_string(i);
    if (*view >= views.size())
      source.refuse(name + " refers to buffer view " + std::to_string(*view) + ", which does not exist");
    const GltfJsonElement& v = views[*view];
    const auto buffer = number(v, "buffer"), length = number(v, "byteLength");
    const uint64_t offset = number(v, "byteOffset").value_or(0);
    if (!buffer || *buffer >= buffers.size() || !length)
      source.refuse(name + "'s buffer view " + std::to_string(*view) + " does not name a buffer and a length");
    const auto end = checkedAdd(offset, *length);
    if (!end || *end > number(buffers[*buffer], "byteLength").value_or(0))
      source.refuse(name + "'s buffer view " + std::to_string(*view) + " reaches past the end of its buffer");
  }
}

// Required extensions lbmshape knows and cannot read: the geometry they
// hold would be missing or wrong. (EXT_meshopt_compression is decoded
// beforehand in GLB files, gltf_meshopt_decoding.hpp.)
const std::set<std::string> unreadableRequiredExtensions = {"KHR_draco_mesh_compression", "EXT_meshopt_compression",
                                                            "KHR_meshopt_compression", "EXT_mesh_gpu_instancing"};

// Required extensions that change nothing lbmshape reads (materials,
// textures, lights, metadata, animations beside the scene it reads) or that
// it reads (quantized positions). Any other required extension is refused:
// the glTF specification has a reader refuse what a file requires and it
// does not know, which may change the geometry.
bool understoodRequiredExtension(const std::string& extension)
{
  static const std::set<std::string> understood = {
      "KHR_mesh_quantization",  "KHR_texture_transform", "KHR_texture_basisu",
      "EXT_texture_webp",       "EXT_texture_avif",      "KHR_lights_punctual",
      "KHR_materials_variants", "KHR_xmp_json_ld",       "KHR_animation_pointer"};
  return understood.count(extension) > 0 || extension.starts_with("KHR_materials_");
}

// `meshoptInAGlb`: whether EXT_meshopt_compression still required in a
// GLB is refused too. Its views are decoded before this check (readGltf),
// so where it is still required the file's structure kept them from being
// decoded, and that is what to say first.
void refuseRequiredExtensions(const std::vector<std::string>& required, bool glb, bool meshoptInAGlb,
                              const MeshSource& source)
{
  for (const std::string& extension : required) {
    if (extension == "EXT_meshopt_compression" && glb && !meshoptInAGlb) continue;
    if (extension == "EXT_meshopt_compression" && !glb)
      source.refuse("it requires EXT_meshopt_compression, which lbmshape decodes in GLB files only (.glb)");
    if (unreadableRequiredExtensions.count(extension))
      source.refuse("it requires " + text::printable(extension) + ", which lbmshape cannot decode");
    if (!understoodRequiredExtension(extension))
      source.refuse("it requires the extension " + text::quoted(shown(extension)) + ", which lbmshape does not know");
  }
}

}  // namespace

std::vector<GltfBufferEntry> checkGltfJson(std::string_view json, bool glb, const MeshSource& source)
{
  GltfJsonScan scan(source);
  nlohmann::json::sax_parse(json.begin(), json.end(), &scan, nlohmann::json::input_format_t::json);
  if (scan.tooDeep)
    source.refuse("its JSON nests more than " + std::to_string(maxGltfJsonDepth) +
                  " levels deep, far beyond any glTF file's structure");
  if (!scan.syntaxError.empty()) source.refuse("its JSON is malformed (" + text::printable(scan.syntaxError) + ")");
  if (scan.containers * bytesPerContainer + scan.scalars * bytesPerScalar > structureBudget(json.size()))
    source.refuse("its JSON holds " + std::to_string(scan.containers + scan.scalars) +
                  " values, more than a glTF file of this size needs");
  // Before anything else of the file is judged: a file whose geometry is
  // compressed fails every other check (accessors without views), and
  // should be refused for what it needs.
  refuseRequiredExtensions(scan.extensionLists.at("extensionsRequired"), glb, false, source);
  if (scan.refusal) std::rethrow_exception(scan.refusal);
  refuseRequiredExtensions(scan.extensionLists.at("extensionsRequired"), glb, true, source);
  checkDefaultScene(scan, source);
  checkBuffers(scan.kept.at("buffers"), glb, scan.extensionLists.at("extensionsUsed"), source);
  checkImageViews(scan, source);

  std::vector<GltfBufferEntry> buffers;
  for (const GltfJsonElement& b : scan.kept.at("buffers")) {
    auto uri = b.strings.find("uri");
    buffers.push_back({uri == b.strings.end() ? std::string() : uri->second, number(b, "byteLength").value_or(0)});
  }
  return buffers;
}

}  // namespace lbmshape
