#include "lbmshape/mesh/ply_header.hpp"

#include <array>
#include <optional>
#include <unordered_set>
#include <utility>

#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {
namespace {

// Both spellings PLY files use: the original names and the sized ones.
constexpr std::array<std::pair<std::string_view, PlyType>, 16> typeNames{{
    {"char", PlyType::Int8},
    {"int8", PlyType::Int8},
    {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},
    {"short", PlyType::Int16},
    {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16},
    {"uint16", PlyType::UInt16},
    {"int", PlyType::Int32},
    {"int32", PlyType::Int32},
    {"uint", PlyType::UInt32},
    {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32},
    {"float32", PlyType::Float32},
    {"double", PlyType::Float64},
    {"float64", PlyType::Float64},
}};

std::optional<PlyType> typeNamed(std::string_view name)
{
  for (const auto& [spelling, type] : typeNames)
    if (spelling == name) return type;
  return std::nullopt;
}

}  // namespace

size_t byteSize(PlyType type)
{
  switch (type) {
  case PlyType::Int8:
  case PlyType::UInt8: return 1;
  case PlyType::Int16:
  case PlyType::UInt16: return 2;
  case PlyType::Int32:
  case PlyType::UInt32:
  case PlyType::Float32: return 4;
  case PlyType::Float64: return 8;
  }
  return 1;
}

bool isInteger(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

size_t PlyElement::leastBytesPerEntry(PlyEncoding encoding) const
{
  size_t bytes = 0;
  for (const PlyProperty& p : properties)
    // In ASCII every value, a list's length included, is at least one
    // character and a separator (the very last one may lack its separator,
    // which the caller allows for).
    bytes += encoding == PlyEncoding::Ascii ? 2 : byteSize(p.isList ? p.countType : p.type);
  return bytes;
}

// Far more than any PLY file has, and small enough that the header's own
// structures stay small whatever the file holds.
constexpr size_t maxElements = 1000, maxProperties = 1000;

PlyHeader parsePlyHeader(const MeshSource& source)
{
  PlyHeader header;
  std::unordered_set<std::string> elementNames;
  std::string_view rest = text::withoutByteOrderMark(source.bytes);
  size_t lineNumber = 0;
  bool sawFormat = false;
  auto fail = [&](const std::string& what) { source.refuse("line " + std::to_string(lineNumber) + ": " + what); };

  while (!rest.empty()) {
    const std::string_view line = text::nextLine(rest);
    ++lineNumber;
    std::string_view words = line;
    const std::string_view keyword = text::nextToken(words);
    if (lineNumber == 1) {
      if (keyword != "ply" || !text::nextToken(words).empty())
        source.refuse("not a PLY file (it must begin with 'ply')");
      continue;
    }
    if (keyword == "comment" || keyword == "obj_info" || keyword.empty()) continue;
    if (keyword == "end_header") {
      if (!sawFormat) fail("the header ends without a 'format' line");
      header.bodyOffset = source.bytes.size() - rest.size();  // counted from the file's start, mark or not
      header.bodyFirstLine = lineNumber + 1;
      return header;
    }
    if (keyword == "format") {
      const std::string_view encoding = text::nextToken(words);
      const std::string_view version = text::nextToken(words);
      if (sawFormat) fail("a second 'format' line");
      if (encoding == "ascii")
        header.encoding = PlyEncoding::Ascii;
      else if (encoding == "binary_little_endian")
        header.encoding = PlyEncoding::BinaryLittleEndian;
      else if (encoding == "binary_big_endian")
        header.encoding = PlyEncoding::BinaryBigEndian;
      else
        fail("unknown format " + text::quoted(encoding) + " (ascii, binary_little_endian or binary_big_endian)");
      if (version.empty() || version[0] != '1') fail("PLY version " + text::quoted(version) + ", not 1.0");
      sawFormat = true;
    } else if (keyword == "element") {
      PlyElement element;
      element.name = std::string(text::nextToken(words));
      const auto count = text::integer(text::nextToken(words));
      if (element.name.empty() || !count || !text::nextToken(words).empty())
        fail(text::quoted(line) + " is not 'element NAME COUNT'");
      if (*count < 0)
        fail("element " + text::quoted(element.name) + " has a negative count (" + std::to_string(*count) + ")");
      if (!elementNames.insert(element.name).second) fail("a second element named " + text::quoted(element.name));
      if (header.elements.size() == maxElements) fail("more than " + std::to_string(maxElements) + " elements");
      element.count = uint64_t(*count);
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) fail("a property before any element");
      if (header.elements.back().properties.size() == maxProperties)
        fail("more than " + std::to_string(maxProperties) + " properties in one element");
      PlyProperty property;
      std::string_view type = text::nextToken(words);
      if (type == "list") {
        property.isList = true;
        const auto countType = typeNamed(text::nextToken(words));
        if (!countType || !isInteger(*countType))
          fail(text::quoted(line) + ": a list's length must have an integer type");
        property.countType = *countType;
        type = text::nextToken(words);
      }
      const auto valueType = typeNamed(type);
      if (!valueType) fail(text::quoted(line) + ": unknown property type " + text::quoted(type));
      property.type = *valueType;
      property.name = std::string(text::nextToken(words));
      if (property.name.empty() || !text::nextToken(words).empty())
        fail(text::quoted(line) + " is not 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
      // Read by name, a property named twice would be read as one of the two.
      for (const PlyProperty& earlier : header.elements.back().properties)
        if (earlier.name == property.name)
          fail(text::quoted(line) + ": element " + text::quoted(header.elements.back().name) +
               " already has a property " + text::quoted(property.name));
      header.elements.back().properties.push_back(std::move(property));
    } else {
      fail("unknown header line " + text::quoted(line));
    }
  }
  source.refuse("the header has no 'end_header' line");
}

}  // namespace lbmshape
