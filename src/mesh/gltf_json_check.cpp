#include "mesh/gltf_json_check.hpp"

#include <nlohmann/json.hpp>

#include "mesh/text_scan.hpp"

namespace lbmshape {
namespace {

// Follows the parser's events with a stack of open containers, deep enough
// to know when a value is buffers[i].uri or buffers[i].byteLength.
class GltfJsonScan : public nlohmann::json_sax<nlohmann::json> {
public:
  std::vector<GltfBufferEntry> buffers;
  bool tooDeep = false;
  std::string syntaxError;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t n) override
  {
    if (inBuffer() && key_ == "byteLength" && n >= 0) buffers.back().byteLength = uint64_t(n);
    return value();
  }
  bool number_unsigned(number_unsigned_t n) override
  {
    if (inBuffer() && key_ == "byteLength") buffers.back().byteLength = n;
    return value();
  }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t& s) override
  {
    if (inBuffer() && key_ == "uri") buffers.back().uri = s;
    return value();
  }
  bool binary(binary_t&) override { return value(); }
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

  bool inBuffer() const
  {
    return stack_.size() == 3 && !stack_[2].array && stack_[1].array && stack_[1].key == "buffers";
  }
  // A value (or a container's start) in its parent: a new buffer begins at
  // each element of the top-level "buffers" array.
  bool value()
  {
    key_.clear();
    return true;
  }
  bool open(bool array)
  {
    if (stack_.size() >= size_t(maxGltfJsonDepth)) {
      tooDeep = true;
      return false;
    }
    stack_.push_back({array, stack_.size() == 1 && !stack_[0].array ? key_ : std::string()});
    if (inBuffer()) buffers.emplace_back();
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

}  // namespace

std::vector<GltfBufferEntry> checkGltfJson(std::string_view json, const MeshSource& source)
{
  GltfJsonScan scan;
  nlohmann::json::sax_parse(json.begin(), json.end(), &scan, nlohmann::json::input_format_t::json);
  if (scan.tooDeep)
    source.refuse("its JSON nests more than " + std::to_string(maxGltfJsonDepth) +
                  " levels deep, far beyond any glTF file's structure");
  if (!scan.syntaxError.empty()) source.refuse("its JSON is malformed (" + text::printable(scan.syntaxError) + ")");
  return std::move(scan.buffers);
}

}  // namespace lbmshape
