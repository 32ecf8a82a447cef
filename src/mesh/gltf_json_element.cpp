#include "lbmshape/mesh/gltf_json_element.hpp"

namespace lbmshape {
namespace {

// The properties of an element that glTF types and lbmshape's reading
// depends on (glTF 2.0, chapter 5).
struct ElementRules {
  std::vector<std::string> wholeNumbers;                       // indices, counts, offsets, enums
  std::vector<std::pair<std::string, uint64_t>> numberArrays;  // with their length; 0 for any
  std::vector<std::string> wholeNumberArrays;                  // lists of indices
};

const std::map<std::string, ElementRules>& rulesByCollection()
{
  static const std::map<std::string, ElementRules> rules = {
      {"nodes",
       {{"camera", "skin", "mesh"},
        {{"translation", 3}, {"rotation", 4}, {"scale", 3}, {"matrix", 16}, {"weights", 0}},
        {"children"}}},
      {"scenes", {{}, {}, {"nodes"}}},
      {"meshes.primitives", {{"indices", "material", "mode"}, {}, {}}},
      {"accessors", {{"bufferView", "byteOffset", "componentType", "count"}, {}, {}}},
      {"bufferViews", {{"buffer", "byteOffset", "byteLength", "byteStride", "target"}, {}, {}}},
      {"buffers", {{"byteLength"}, {}, {}}},
      {"images", {{"bufferView"}, {}, {}}},
  };
  return rules;
}

std::string elementName(const std::string& collection, const std::vector<uint64_t>& index)
{
  if (collection == "meshes.primitives")
    return "mesh " + std::to_string(index.at(0)) + " primitive " + std::to_string(index.at(1));
  static const std::map<std::string, std::string> singular = {{"nodes", "node"},         {"scenes", "scene"},
                                                              {"accessors", "accessor"}, {"bufferViews", "buffer view"},
                                                              {"buffers", "buffer"},     {"images", "image"}};
  return singular.at(collection) + " " + std::to_string(index.back());
}

std::string numbers(uint64_t length) { return length == 0 ? "numbers" : std::to_string(length) + " numbers"; }

std::string described(const GltfJsonElement::Array& array)
{
  const std::string count = std::to_string(array.count);
  if (array.count == 0) return "an empty array";
  if (!array.allNumbers) return "an array of " + count + " values, not all numbers";
  return "an array of " + count + (array.count == 1 ? " number" : " numbers");
}

}  // namespace

bool isCheckedGltfCollection(const std::string& collection) { return rulesByCollection().count(collection) > 0; }

void checkGltfElement(const std::string& collection, const std::vector<uint64_t>& index, const GltfJsonElement& element,
                      const MeshSource& source)
{
  const ElementRules& rules = rulesByCollection().at(collection);
  const std::string name = elementName(collection, index);
  auto refuse = [&](const std::string& key, const std::string& should) {
    auto array = element.arrays.find(key);
    const std::string is = array == element.arrays.end() ? element.written.at(key) : described(array->second);
    source.refuse(name + "'s \"" + key + "\" must be " + should + "; it is " + is);
  };
  for (const std::string& key : rules.wholeNumbers)
    if (element.written.count(key) && !element.wholeNumbers.count(key)) refuse(key, "a whole number of 0 or more");
  for (const auto& [key, length] : rules.numberArrays) {
    if (!element.written.count(key)) continue;
    auto array = element.arrays.find(key);
    if (array == element.arrays.end() || !array->second.allNumbers || (length != 0 && array->second.count != length))
      refuse(key, "an array of " + numbers(length));
  }
  for (const std::string& key : rules.wholeNumberArrays) {
    if (!element.written.count(key)) continue;
    auto array = element.arrays.find(key);
    if (array == element.arrays.end() || !array->second.allWholeNumbers)
      refuse(key, "an array of whole numbers of 0 or more");
  }

  if (collection == "nodes" && element.written.count("matrix"))
    for (const char* key : {"translation", "rotation", "scale"})
      if (element.written.count(key))
        source.refuse(name + " has both a matrix and a " + key + " (glTF gives a node one or the other)");
  if (collection == "meshes.primitives") {
    // 0 to 6: points, lines, line loop, line strip, triangles, strip, fan.
    auto mode = element.wholeNumbers.find("mode");
    if (mode != element.wholeNumbers.end() && mode->second > 6)
      source.refuse(name + "'s mode " + std::to_string(mode->second) + " is not a glTF primitive mode (0 to 6)");
  }
}

}  // namespace lbmshape
