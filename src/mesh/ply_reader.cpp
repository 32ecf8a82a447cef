// Why lbmshape parses PLY itself: OpenMesh's PLY reader crashes on a
// property before any element, loops forever on a header without
// end_header or on a negative list length, prints to stderr on legal files
// it cannot convert (e.g. "property uint x"), and reserves whatever a
// header's counts ask for. Here every count is checked against the bytes
// that are left before anything is reserved, and every value type PLY
// defines converts to a coordinate or an index.
#include "lbmshape/mesh/ply_reader.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "lbmshape/core/log.hpp"
#include "lbmshape/mesh/ply_header.hpp"
#include "lbmshape/mesh/fan_triangulation.hpp"
#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {
namespace {

// A fault in the body; the element loop adds where it happened.
struct BodyFault {
  std::string what;
};

// The values of a binary body, in either byte order.
class BinaryValues {
public:
  BinaryValues(std::string_view body, bool bigEndian)
      : rest_(body), swap_(bigEndian != (std::endian::native == std::endian::big))
  {}

  double number(PlyType type) { return read(type); }
  int64_t integer(PlyType type) { return int64_t(read(type)); }  // only asked of integer types
  void skip(PlyType type) { take(byteSize(type)); }
  size_t bytesLeft() const { return rest_.size(); }
  size_t leastBytesPerValue(PlyType type) const { return byteSize(type); }
  // Binary entries have no lines to keep to.
  void beginEntry() {}
  void endEntry() {}
  // Bytes left that are more than padding (line ends, NULs).
  size_t dataLeft() const
  {
    return size_t(std::count_if(rest_.begin(), rest_.end(), [](char c) { return !text::isSpace(c) && c != '\0'; }));
  }

private:
  const char* take(size_t bytes)
  {
    if (rest_.size() < bytes) throw BodyFault{"the file ends in the middle of it"};
    const char* p = rest_.data();
    rest_.remove_prefix(bytes);
    return p;
  }

  template <typename T>
  T load(const char* p) const
  {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, p, sizeof(T));
    if (swap_)
      for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  double read(PlyType type)
  {
    const char* p = take(byteSize(type));
    switch (type) {
    case PlyType::Int8: return load<int8_t>(p);
    case PlyType::UInt8: return load<uint8_t>(p);
    case PlyType::Int16: return load<int16_t>(p);
    case PlyType::UInt16: return load<uint16_t>(p);
    case PlyType::Int32: return load<int32_t>(p);
    case PlyType::UInt32: return load<uint32_t>(p);
    case PlyType::Float32: return load<float>(p);
    case PlyType::Float64: return load<double>(p);
    }
    return 0;
  }

  std::string_view rest_;
  bool swap_;
};

// The values of an ASCII body: whitespace-separated numbers.
class AsciiValues {
public:
  explicit AsciiValues(std::string_view body) : rest_(body) {}

  double number(PlyType)
  {
    const std::string_view token = next();
    double value = 0;
    std::string_view digits = token[0] == '+' ? token.substr(1) : token;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error != std::errc() || end != digits.data() + digits.size())
      throw BodyFault{text::quoted(token) + " is not a number"};
    return value;
  }
  int64_t integer(PlyType)
  {
    const std::string_view token = next();
    const auto value = text::integer(token);
    if (!value) throw BodyFault{text::quoted(token) + " is not an integer"};
    return *value;
  }
  void skip(PlyType) { next(); }
  size_t bytesLeft() const { return rest_.size(); }
  size_t leastBytesPerValue(PlyType) const { return 1; }
  size_t line() const { return line_; }

  // Each entry on a line of its own, as PLY writes them: a line with a
  // value too few or too many (a count in the header one too high, a vertex
  // of two coordinates) is refused here, where reading the values as one
  // stream would shift every later one silently onto the wrong property.
  void beginEntry() { valuesOnLine_ = 0; }
  void endEntry()
  {
    rest_ = text::skipBlanks(rest_);
    if (!rest_.empty() && rest_[0] != '\n') {
      std::string_view rest = rest_;
      throw BodyFault{"its line holds more values than the header's properties (" + std::to_string(valuesOnLine_) +
                      "): " + text::quoted(text::nextLine(rest)) + " is left over"};
    }
  }
  // Whether anything but blanks and line ends follows.
  bool anythingLeft() const
  {
    return std::any_of(rest_.begin(), rest_.end(), [](char c) { return !text::isSpace(c); });
  }

private:
  std::string_view next()
  {
    size_t start = 0;
    while (start < rest_.size() && text::isSpace(rest_[start])) {
      if (rest_[start++] == '\n') {
        if (valuesOnLine_ > 0)
          throw BodyFault{"its line ends after " + std::to_string(valuesOnLine_) +
                          " values, before the header's properties do"};
        ++line_;
      }
    }
    rest_.remove_prefix(start);
    const std::string_view token = text::nextToken(rest_);
    if (token.empty()) throw BodyFault{"the file ends in the middle of it"};
    ++valuesOnLine_;
    return token;
  }

  std::string_view rest_;
  size_t line_ = 0;          // line ends passed, from the start of the body
  size_t valuesOnLine_ = 0;  // of the entry being read
};

// Where x, y, z and the face indices sit among their element's properties.
struct Layout {
  const PlyElement* vertex = nullptr;
  int coordinate[3] = {-1, -1, -1};
  int colour[3] = {-1, -1, -1};  // red, green, blue; all three or none
  bool coloured() const { return colour[0] >= 0 && colour[1] >= 0 && colour[2] >= 0; }
  const PlyElement* face = nullptr;
  int indices = -1;
};

Layout layoutOf(const PlyHeader& header, const MeshSource& source)
{
  Layout layout;
  for (const PlyElement& element : header.elements) {
    if (element.name == "vertex") layout.vertex = &element;
    if (element.name == "face") layout.face = &element;
  }
  if (!layout.vertex) source.refuse("it has no 'vertex' element");
  const auto& vertexProperties = layout.vertex->properties;
  for (size_t p = 0; p < vertexProperties.size(); ++p)
    for (int k = 0; k < 3; ++k)
      if (vertexProperties[p].name == std::string(1, char('x' + k))) {
        if (vertexProperties[p].isList)
          source.refuse("vertex property " + text::quoted(vertexProperties[p].name) + " is a list");
        layout.coordinate[k] = int(p);
      }
  for (int k = 0; k < 3; ++k)
    if (layout.coordinate[k] < 0)
      source.refuse("the vertex element has no '" + std::string(1, char('x' + k)) + "' property");
  // Vertex colours, as scanners and MeshLab write them; ignored unless all
  // three are plain values.
  static const char* const colourNames[3] = {"red", "green", "blue"};
  for (size_t p = 0; p < vertexProperties.size(); ++p)
    for (int k = 0; k < 3; ++k)
      if (vertexProperties[p].name == colourNames[k] && !vertexProperties[p].isList) layout.colour[k] = int(p);
  if (layout.face) {
    const auto& faceProperties = layout.face->properties;
    for (size_t p = 0; p < faceProperties.size(); ++p)
      if (faceProperties[p].name == "vertex_indices" || faceProperties[p].name == "vertex_index")
        layout.indices = int(p);
    if (layout.indices < 0) source.refuse("the face element has no 'vertex_indices' list");
    const PlyProperty& indices = faceProperties[size_t(layout.indices)];
    if (!indices.isList || !isInteger(indices.type))
      source.refuse("the face element's " + text::quoted(indices.name) + " is not a list of integers");
  }
  return layout;
}

template <typename Values>
class BodyReader {
public:
  BodyReader(const PlyHeader& header, const Layout& layout, Values& values)
      : header_(header), layout_(layout), values_(values)
  {}

  void read(const MeshSource& source, TriangleMesh& mesh)
  {
    for (const PlyElement& element : header_.elements) {
      if (element.properties.empty()) continue;  // nothing to read, however many entries
      for (uint64_t entry = 0; entry < element.count; ++entry) {
        try {
          values_.beginEntry();
          if (&element == layout_.vertex)
            readVertex(element, mesh);
          else if (&element == layout_.face)
            readFace(element, mesh);
          else
            skipEntry(element);
          values_.endEntry();
        } catch (const BodyFault& fault) {
          source.refuse(where() + text::printable(element.name, 60) + " " + std::to_string(entry + 1) + " of " +
                        std::to_string(element.count) + ": " + fault.what);
        }
      }
    }
  }

  size_t shortFaces() const { return shortFaces_; }

private:
  std::string where() const
  {
    if constexpr (std::is_same_v<Values, AsciiValues>)
      return "line " + std::to_string(header_.bodyFirstLine + values_.line()) + ": ";
    else
      return "";
  }

  void readVertex(const PlyElement& element, TriangleMesh& mesh)
  {
    glm::dvec3 p(0.0);
    glm::vec3 colour(1.0f);
    for (size_t i = 0; i < element.properties.size(); ++i) {
      const PlyProperty& property = element.properties[i];
      if (property.isList) {
        skipList(property);
        continue;
      }
      const double value = values_.number(property.type);
      for (int k = 0; k < 3; ++k) {
        if (layout_.coordinate[k] == int(i)) p[k] = value;
        if (layout_.colour[k] == int(i)) colour[k] = colourValue(value, property.type);
      }
    }
    mesh.positions.push_back(p);
    if (layout_.coloured()) mesh.colours.push_back(colour);
  }

  // Integers count up to their type's largest value (255 for uchar, the
  // usual), floating-point values up to 1.
  static float colourValue(double value, PlyType type)
  {
    const double full = type == PlyType::UInt16 || type == PlyType::Int16 ? 65535.0 : isInteger(type) ? 255.0 : 1.0;
    return std::isfinite(value) ? float(std::clamp(value / full, 0.0, 1.0)) : 0.0f;
  }

  void readFace(const PlyElement& element, TriangleMesh& mesh)
  {
    corners_.clear();
    for (size_t i = 0; i < element.properties.size(); ++i) {
      const PlyProperty& property = element.properties[i];
      if (int(i) != layout_.indices) {
        property.isList ? skipList(property) : values_.skip(property.type);
        continue;
      }
      const uint64_t length = listLength(property);
      for (uint64_t c = 0; c < length; ++c) {
        const int64_t index = values_.integer(property.type);
        if (index < 0 || uint64_t(index) >= layout_.vertex->count)
          throw BodyFault{"it refers to vertex " + std::to_string(index) + ", but there are only " +
                          std::to_string(layout_.vertex->count) + " vertices (numbered from 0)"};
        corners_.push_back(uint32_t(index));
      }
    }
    if (corners_.size() < 3) {
      ++shortFaces_;
      return;
    }
    appendFan(corners_, mesh.triangles);
  }

  void skipEntry(const PlyElement& element)
  {
    for (const PlyProperty& property : element.properties)
      property.isList ? skipList(property) : values_.skip(property.type);
  }

  void skipList(const PlyProperty& property)
  {
    const uint64_t length = listLength(property);
    for (uint64_t c = 0; c < length; ++c) values_.skip(property.type);
  }

  // A list's length, refused when negative or longer than the rest of the file.
  uint64_t listLength(const PlyProperty& property)
  {
    const int64_t length = values_.integer(property.countType);
    if (length < 0) throw BodyFault{"a list of " + std::to_string(length) + " items"};
    if (uint64_t(length) > values_.bytesLeft() / values_.leastBytesPerValue(property.type) + 1)
      throw BodyFault{"a list of " + std::to_string(length) + " items, longer than the rest of the file"};
    return uint64_t(length);
  }

  const PlyHeader& header_;
  const Layout& layout_;
  Values& values_;
  std::vector<uint32_t> corners_;
  size_t shortFaces_ = 0;
};

// Every element's entries need at least so many bytes: a header whose counts
// the body cannot hold is refused before anything is reserved for them.
void requireCountsFit(const MeshSource& source, const PlyHeader& header, size_t bodyBytes)
{
  uint64_t needed = 0;
  for (const PlyElement& element : header.elements) {
    const size_t least = element.leastBytesPerEntry(header.encoding);
    // + 1: the last ASCII value may end the file without a separator.
    if (least > 0 && element.count > (bodyBytes + 1) / least)
      source.refuse("element " + text::quoted(element.name) + " claims " + std::to_string(element.count) +
                    " entries, more than the rest of the file can hold");
    needed += element.count * least;  // both terms <= bodyBytes + 1: no overflow
    if (needed > bodyBytes + 1)
      source.refuse("the header's element counts need more than the " + std::to_string(bodyBytes) +
                    " bytes that follow the header");
  }
}

template <typename Values>
size_t readBody(const MeshSource& source, const PlyHeader& header, const Layout& layout, Values values,
                TriangleMesh& mesh)
{
  // Exact for the vertices (counts were checked against the body); the
  // triangles grow as faces are read, since a face may be empty.
  mesh.positions.reserve(size_t(layout.vertex->count));
  if (layout.coloured()) mesh.colours.reserve(size_t(layout.vertex->count));
  BodyReader<Values> reader(header, layout, values);
  reader.read(source, mesh);
  // Entries the header does not count (a face count one too low) would be
  // left out silently: an open mesh, or a part missing.
  if constexpr (std::is_same_v<Values, AsciiValues>) {
    if (values.anythingLeft())
      source.refuse("values follow line " + std::to_string(header.bodyFirstLine + values.line()) +
                    ", the last entry the header counts (are its element counts too low?)");
  } else if (values.dataLeft() > 0) {
    log::warning(source.name + ": " + std::to_string(values.bytesLeft()) +
                 " bytes follow the last entry the header counts; they were not read (are its element counts too "
                 "low?)");
  }
  return reader.shortFaces();
}

}  // namespace

TriangleMesh readPly(const MeshSource& source)
{
  const PlyHeader header = parsePlyHeader(source);
  const Layout layout = layoutOf(header, source);
  if (layout.vertex->count > uint64_t(UINT32_MAX))
    source.refuse("it has " + std::to_string(layout.vertex->count) +
                  " vertices, more than the 2^32 - 1 lbmshape can index");
  const std::string_view body = source.bytes.substr(header.bodyOffset);

  requireCountsFit(source, header, body.size());

  TriangleMesh mesh;
  size_t shortFaces = 0;
  switch (header.encoding) {
  case PlyEncoding::Ascii: shortFaces = readBody(source, header, layout, AsciiValues(body), mesh); break;
  case PlyEncoding::BinaryLittleEndian:
    shortFaces = readBody(source, header, layout, BinaryValues(body, false), mesh);
    break;
  case PlyEncoding::BinaryBigEndian:
    shortFaces = readBody(source, header, layout, BinaryValues(body, true), mesh);
    break;
  }
  warnOfShortFaces(source.name, shortFaces);
  return mesh;
}

}  // namespace lbmshape
