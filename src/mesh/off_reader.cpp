// Why lbmshape parses OFF itself: OpenMesh's OFF reader hangs and grows
// without end on a negative or oversized count, on a lone "OFF", and on
// "OFF BINARY" followed by text. Here counts are checked against the bytes
// left before anything is reserved, and every line is read at most once.
#include "lbmshape/mesh/off_reader.hpp"

#include <bit>
#include <cstring>

#include "lbmshape/core/log.hpp"
#include "lbmshape/mesh/fan_triangulation.hpp"
#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {
namespace {

// What the header keyword announces.
struct OffHeader {
  bool binary = false;
  int extraVertexFloats = 0;  // binary only: N a normal (3), C a colour (4), ST texture coordinates (2)
};

// The lines of an ASCII OFF file that hold something, comments removed.
class OffLines {
public:
  explicit OffLines(const MeshSource& source) : source_(source), rest_(text::withoutByteOrderMark(source.bytes)) {}

  // The next line with content; empty at the end of the file.
  std::string_view next()
  {
    while (!rest_.empty()) {
      std::string_view line = text::nextLine(rest_);
      ++lineNumber_;
      line = line.substr(0, line.find('#'));
      std::string_view probe = line;
      if (!text::nextToken(probe).empty()) return line;
    }
    return {};
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    source_.refuse("line " + std::to_string(lineNumber_) + ": " + what);
  }
  std::string_view rest() const { return rest_; }

private:
  const MeshSource& source_;
  std::string_view rest_;
  size_t lineNumber_ = 0;
};

// Reads the keyword, if any; `line` keeps what follows it on its line.
OffHeader readKeyword(OffLines& lines, std::string_view& line)
{
  OffHeader header;
  std::string_view words = line;
  std::string_view keyword = text::nextToken(words);
  if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF") return header;  // no keyword: counts first
  std::string_view prefix = keyword.substr(0, keyword.size() - 3);
  if (prefix.starts_with("ST")) header.extraVertexFloats += 2, prefix.remove_prefix(2);
  if (prefix.starts_with("C")) header.extraVertexFloats += 4, prefix.remove_prefix(1);
  if (prefix.starts_with("N")) header.extraVertexFloats += 3, prefix.remove_prefix(1);
  if (prefix == "4" || prefix == "n")
    lines.fail(text::quoted(keyword) + ": only three-dimensional OFF files can be read (not 4OFF or nOFF)");
  if (!prefix.empty()) lines.fail(text::quoted(keyword) + " is not an OFF header keyword");
  std::string_view after = words;
  if (text::nextToken(after) == "BINARY") {
    header.binary = true;
    words = after;
  }
  line = words;
  return header;
}

struct Counts {
  uint64_t vertices = 0, faces = 0;
};

// "V F E" (E, the edge count, is not used, and some files leave it out).
Counts readCounts(OffLines& lines, std::string_view words)
{
  if (text::skipBlanks(words).empty()) words = lines.next();
  if (words.empty()) lines.fail("the file ends before the vertex and face counts");
  const auto vertices = text::integer(text::nextToken(words));
  const auto faces = text::integer(text::nextToken(words));
  if (!vertices || !faces) lines.fail("expected the counts 'vertices faces edges'");
  if (*vertices < 0 || *faces < 0)
    lines.fail("negative counts (" + std::to_string(*vertices) + " vertices, " + std::to_string(*faces) + " faces)");
  return {uint64_t(*vertices), uint64_t(*faces)};
}

size_t readAsciiBody(const MeshSource& source, OffLines& lines, const Counts& counts, TriangleMesh& mesh)
{
  // A vertex line takes at least 6 bytes ("0 0 0\n"), a face line 2 ("0\n").
  const size_t left = lines.rest().size() + 1;
  if (counts.vertices > left / 6 || counts.faces > left / 2 || counts.vertices * 6 + counts.faces * 2 > left)
    source.refuse("the counts (" + std::to_string(counts.vertices) + " vertices, " + std::to_string(counts.faces) +
                  " faces) are more than the rest of the file can hold");
  mesh.positions.reserve(counts.vertices);  // the triangles grow as faces are read: a face may add none
  for (uint64_t v = 0; v < counts.vertices; ++v) {
    std::string_view line = lines.next();
    if (line.empty())
      source.refuse("the file ends after " + std::to_string(v) + " of " + std::to_string(counts.vertices) +
                    " vertices");
    std::string_view words = line;
    glm::dvec3 p;
    for (int k = 0; k < 3; ++k) {
      const auto value = text::coordinate(text::nextToken(words));
      if (!value) lines.fail(text::quoted(line) + " is " + text::notAVertex);
      p[k] = *value;
    }
    mesh.positions.push_back(p);
  }
  size_t shortFaces = 0;
  std::vector<uint32_t> corners;
  for (uint64_t f = 0; f < counts.faces; ++f) {
    std::string_view line = lines.next();
    if (line.empty())
      source.refuse("the file ends after " + std::to_string(f) + " of " + std::to_string(counts.faces) + " faces");
    std::string_view words = line;
    const auto size = text::integer(text::nextToken(words));
    if (!size || *size < 0) lines.fail(text::quoted(line) + " does not begin with a number of corners");
    corners.clear();
    for (int64_t c = 0; c < *size; ++c) {
      const std::string_view token = text::nextToken(words);
      if (token.empty())
        lines.fail(text::quoted(line) + " announces " + std::to_string(*size) + " corners but gives " +
                   std::to_string(c));
      const auto index = text::integer(token);
      if (!index || *index < 0 || uint64_t(*index) >= counts.vertices)
        lines.fail(text::quoted(line) + " refers to vertex " + text::quoted(token) + ", but there are only " +
                   std::to_string(counts.vertices) + " vertices (numbered from 0)");
      corners.push_back(uint32_t(*index));
    }
    if (corners.size() < 3) ++shortFaces;
    appendFan(corners, mesh.triangles);
  }
  // More after the faces the header counts: a count too low, which left
  // the last faces out.
  if (const std::string_view more = lines.next(); !more.empty())
    lines.fail(text::quoted(more) + " follows the last of the " + std::to_string(counts.faces) +
               " faces the header counts (is its face count too low?)");
  return shortFaces;
}

// Geomview's binary OFF: big-endian 32-bit integers and floats.
class BigEndianWords {
public:
  BigEndianWords(const MeshSource& source, std::string_view bytes) : source_(source), rest_(bytes) {}

  uint32_t word(const char* what)
  {
    if (rest_.size() < 4) source_.refuse(std::string("the binary body ends before ") + what);
    uint32_t value;
    std::memcpy(&value, rest_.data(), 4);
    rest_.remove_prefix(4);
    return std::endian::native == std::endian::little ? __builtin_bswap32(value) : value;
  }
  int32_t integer(const char* what) { return std::bit_cast<int32_t>(word(what)); }
  float number(const char* what) { return std::bit_cast<float>(word(what)); }
  size_t wordsLeft() const { return rest_.size() / 4; }

private:
  const MeshSource& source_;
  std::string_view rest_;
};

size_t readBinaryBody(const MeshSource& source, std::string_view body, const OffHeader& header, TriangleMesh& mesh)
{
  BigEndianWords words(source, body);
  const int32_t vertices = words.integer("the counts"), faces = words.integer("the counts");
  words.integer("the counts");  // edges
  if (vertices < 0 || faces < 0)
    source.refuse("binary OFF with negative counts (" + std::to_string(vertices) + " vertices, " +
                  std::to_string(faces) + " faces)");
  const size_t perVertex = 3 + size_t(header.extraVertexFloats);
  // Each face takes at least two words: its corner count and its colour count.
  if (size_t(vertices) * perVertex + size_t(faces) * 2 > words.wordsLeft())
    source.refuse("the binary counts (" + std::to_string(vertices) + " vertices, " + std::to_string(faces) +
                  " faces) are more than the rest of the file can hold");
  mesh.positions.reserve(size_t(vertices));
  mesh.triangles.reserve(size_t(faces));
  for (int32_t v = 0; v < vertices; ++v) {
    glm::dvec3 p;
    for (int k = 0; k < 3; ++k) p[k] = words.number("the last vertex");
    for (int k = 0; k < header.extraVertexFloats; ++k) words.number("the last vertex");
    mesh.positions.push_back(p);
  }
  size_t shortFaces = 0;
  std::vector<uint32_t> corners;
  for (int32_t f = 0; f < faces; ++f) {
    const int32_t size = words.integer("the last face");
    if (size < 0 || size_t(size) > words.wordsLeft())
      source.refuse("binary face " + std::to_string(f) + " announces " + std::to_string(size) + " corners");
    corners.clear();
    for (int32_t c = 0; c < size; ++c) {
      const int32_t index = words.integer("the last face");
      if (index < 0 || index >= vertices)
        source.refuse("binary face " + std::to_string(f) + " refers to vertex " + std::to_string(index) +
                      ", but there are only " + std::to_string(vertices) + " vertices (numbered from 0)");
      corners.push_back(uint32_t(index));
    }
    const int32_t colours = words.integer("the last face");
    if (colours < 0 || colours > 4)
      source.refuse("binary face " + std::to_string(f) + " has " + std::to_string(colours) + " colour components");
    for (int32_t c = 0; c < colours; ++c) words.number("the last face");
    if (corners.size() < 3) ++shortFaces;
    appendFan(corners, mesh.triangles);
  }
  return shortFaces;
}

}  // namespace

TriangleMesh readOff(const MeshSource& source)
{
  OffLines lines(source);
  std::string_view first = lines.next();
  if (first.empty()) source.refuse("it holds nothing but comments and blank lines");
  const OffHeader header = readKeyword(lines, first);
  TriangleMesh mesh;
  size_t shortFaces = 0;
  if (header.binary) {
    shortFaces = readBinaryBody(source, lines.rest(), header, mesh);
  } else {
    const Counts counts = readCounts(lines, first);
    if (counts.vertices > uint64_t(UINT32_MAX)) source.refuse("more vertices than lbmshape can index (2^32 - 1)");
    shortFaces = readAsciiBody(source, lines, counts, mesh);
  }
  warnOfShortFaces(source.name, shortFaces);
  return mesh;
}

}  // namespace lbmshape
