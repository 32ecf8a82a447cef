#include "lbmshape/mesh/gltf_json_element.hpp"

#include <set>

namespace lbmshape {
namespace {

// The properties of an element that glTF types and lbmshape's reading
// depends on (glTF 2.0, chapter 5).
struct ElementRules {
  std::vector<std::string> wholeNumbers{};                       // indices, counts, offsets, enums
  std::vector<std::pair<std::string, uint64_t>> numberArrays{};  // with their length; 0 for any
  std::vector<std::string> wholeNumberArrays{};                  // lists of indices
  std::vector<std::string> booleans{}, strings{}, objects{};
  std::vector<std::string> objectArrays{}, stringArrays{};
  bool everyValueWhole = false;  // a map of names to indices (attributes)
};

const std::map<std::string, ElementRules>& rulesByCollection()
{
  static const std::map<std::string, ElementRules> rules = {
      {"",
       {.wholeNumbers = {"scene"},
        .objectArrays = {"accessors", "animations", "buffers", "bufferViews", "cameras", "images", "materials",
                         "meshes", "nodes", "samplers", "scenes", "skins", "textures"},
        .stringArrays = {"extensionsUsed", "extensionsRequired"}}},
      {"nodes",
       {.wholeNumbers = {"camera", "skin", "mesh"},
        .numberArrays = {{"translation", 3}, {"rotation", 4}, {"scale", 3}, {"matrix", 16}, {"weights", 0}},
        .wholeNumberArrays = {"children"}}},
      {"scenes", {.wholeNumberArrays = {"nodes"}}},
      {"meshes", {.numberArrays = {{"weights", 0}}, .objectArrays = {"primitives"}}},
      {"meshes.primitives",
       {.wholeNumbers = {"indices", "material", "mode"}, .objects = {"attributes"}, .objectArrays = {"targets"}}},
      {"meshes.primitives.attributes", {.everyValueWhole = true}},
      {"meshes.primitives.targets", {.everyValueWhole = true}},
      {"accessors",
       {.wholeNumbers = {"bufferView", "byteOffset", "componentType", "count"},
        .numberArrays = {{"min", 0}, {"max", 0}},
        .booleans = {"normalized"},
        .strings = {"type"},
        .objects = {"sparse"}}},
      {"accessors.sparse", {.wholeNumbers = {"count"}, .objects = {"indices", "values"}}},
      {"accessors.sparse.indices", {.wholeNumbers = {"bufferView", "byteOffset", "componentType"}}},
      {"accessors.sparse.values", {.wholeNumbers = {"bufferView", "byteOffset"}}},
      {"bufferViews", {.wholeNumbers = {"buffer", "byteOffset", "byteLength", "byteStride", "target"}}},
      {"buffers", {.wholeNumbers = {"byteLength"}}},
      {"images", {.wholeNumbers = {"bufferView"}}},
  };
  return rules;
}

std::string described(const GltfJsonElement::Array& array)
{
  const std::string count = std::to_string(array.count);
  if (array.count == 0) return "an empty array";
  if (!array.allNumbers)
    return "an array of " + count + (array.count == 1 ? " value" : " values") + ", not all numbers";
  return "an array of " + count + (array.count == 1 ? " number" : " numbers");
}

}  // namespace

bool isCheckedGltfCollection(const std::string& collection, bool inAnArray)
{
  // The elements that are an object's value, not an array's: "scenes" as an
  // object is refused by its holder's rules, not taken for a scene.
  static const std::set<std::string> objectValues = {"meshes.primitives.attributes", "accessors.sparse",
                                                     "accessors.sparse.indices", "accessors.sparse.values"};
  const bool objectValue = objectValues.count(collection) > 0;
  return rulesByCollection().count(collection) > 0 && inAnArray != objectValue;
}

std::string gltfElementName(const std::string& collection, const std::vector<uint64_t>& index)
{
  const auto at = [&](size_t k) { return std::to_string(index.at(k)); };
  if (collection.empty()) return "its top level";
  if (collection.starts_with("meshes.primitives")) {
    const std::string primitive = "mesh " + at(0) + " primitive " + at(1);
    if (collection == "meshes.primitives.attributes") return primitive + "'s attributes";
    if (collection == "meshes.primitives.targets") return primitive + "'s morph target " + at(2);
    return primitive;
  }
  if (collection.starts_with("accessors.sparse")) {
    const std::string sparse = "accessor " + at(0) + "'s sparse";
    if (collection == "accessors.sparse") return sparse;
    return sparse + (collection.ends_with("indices") ? " indices" : " values");
  }
  static const std::map<std::string, std::string> singular = {{"nodes", "node"},
                                                              {"scenes", "scene"},
                                                              {"meshes", "mesh"},
                                                              {"accessors", "accessor"},
                                                              {"bufferViews", "buffer view"},
                                                              {"buffers", "buffer"},
                                                              {"images", "image"}};
  return singular.at(collection) + " " + at(index.size() - 1);
}

void checkGltfElement(const std::string& collection, const std::vector<uint64_t>& index, const GltfJsonElement& element,
                      const MeshSource& source)
{
  const ElementRules& rules = rulesByCollection().at(collection);
  const std::string name = gltfElementName(collection, index);
  // "node 0's", "its"; "accessor 0's sparse indices:" where the name is one already.
  const std::string possessive = collection.empty()                      ? "its"
                                 : name.find("'s ") != std::string::npos ? name + ":"
                                                                         : name + "'s";
  auto refuse = [&](const std::string& key, const std::string& should) {
    auto array = element.arrays.find(key);
    const std::string is = array == element.arrays.end() ? element.written.at(key) : described(array->second);
    source.refuse(possessive + " \"" + key + "\" must be " + should + "; it is " + is);
  };
  auto kindOf = [&](const std::string& key) { return element.kinds.at(key); };
  auto array = [&](const std::string& key) -> const GltfJsonElement::Array* {
    auto found = element.arrays.find(key);
    return found == element.arrays.end() ? nullptr : &found->second;
  };

  // Each given key of `keys` of this kind, or an array all of whose values pass `all`.
  const auto requireKind = [&](const std::vector<std::string>& keys, JsonKind kind, const std::string& should) {
    for (const std::string& key : keys)
      if (element.kinds.count(key) && kindOf(key) != kind) refuse(key, should);
  };
  const auto requireArrayOf = [&](const std::vector<std::string>& keys, bool GltfJsonElement::Array::*all,
                                  const std::string& should) {
    for (const std::string& key : keys)
      if (const auto* a = array(key); element.kinds.count(key) && (!a || !(a->*all))) refuse(key, should);
  };

  for (const std::string& key : rules.wholeNumbers)
    if (element.kinds.count(key) && !element.wholeNumbers.count(key)) refuse(key, "a whole number of 0 or more");
  for (const auto& [key, length] : rules.numberArrays) {
    if (!element.kinds.count(key)) continue;
    const auto* a = array(key);
    if (!a || !a->allNumbers || (length != 0 && a->count != length))
      refuse(key, "an array of " + (length == 0 ? std::string("numbers") : std::to_string(length) + " numbers"));
  }
  requireArrayOf(rules.wholeNumberArrays, &GltfJsonElement::Array::allWholeNumbers,
                 "an array of whole numbers of 0 or more");
  requireArrayOf(rules.objectArrays, &GltfJsonElement::Array::allObjects, "an array of objects");
  requireArrayOf(rules.stringArrays, &GltfJsonElement::Array::allStrings, "an array of strings");
  requireKind(rules.booleans, JsonKind::Boolean, "true or false");
  requireKind(rules.strings, JsonKind::String, "a string");
  requireKind(rules.objects, JsonKind::Object, "an object");
  if (rules.everyValueWhole)
    for (const auto& [key, kind] : element.kinds)
      if (!element.wholeNumbers.count(key))
        source.refuse(possessive + " \"" + key + "\" must be an accessor's index; it is " + element.written.at(key));

  if (collection == "nodes" && element.kinds.count("matrix"))
    for (const char* key : {"translation", "rotation", "scale"})
      if (element.kinds.count(key))
        source.refuse(name + " has both a matrix and a " + key + " (glTF gives a node one or the other)");
  if (collection == "meshes.primitives") {
    // 0 to 6: points, lines, line loop, line strip, triangles, strip, fan.
    auto mode = element.wholeNumbers.find("mode");
    if (mode != element.wholeNumbers.end() && mode->second > 6)
      source.refuse(name + "'s mode " + std::to_string(mode->second) + " is not a glTF primitive mode (0 to 6)");
  }
}

}  // namespace lbmshape
