// Why lbmshape parses STL itself: OpenMesh's ASCII STL reader silently skips
// a vertex it cannot parse ("nan", "abc", two coordinates, 1e39) and drops a
// facet with four vertices, where the same values in an OBJ file are an
// error. Binary STL goes straight into an array and is then welded.
#include "lbmshape/mesh/stl_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

#include "lbmshape/mesh/compressed_file.hpp"
#include "lbmshape/mesh/text_scan.hpp"
#include "lbmshape/mesh/vertex_welding.hpp"

namespace lbmshape {
namespace {

constexpr size_t headerBytes = 80, countBytes = 4, triangleBytes = 50;

bool looksBinary(std::string_view bytes, uint64_t& triangles)
{
  if (bytes.size() < headerBytes + countBytes) return false;
  uint32_t count;
  std::memcpy(&count, bytes.data() + headerBytes, countBytes);  // little-endian, as STL is
  triangles = count;
  return bytes.size() == headerBytes + countBytes + triangleBytes * uint64_t(count);
}

std::vector<glm::dvec3> readBinaryCorners(const MeshSource& source, uint64_t triangles)
{
  std::vector<glm::dvec3> corners(3 * triangles);
  const char* p = source.bytes.data() + headerBytes + countBytes;
  for (uint64_t t = 0; t < triangles; ++t, p += triangleBytes) {
    float xyz[9];
    std::memcpy(xyz, p + 12, sizeof xyz);  // after the facet normal, which lbmshape does not use
    for (int k = 0; k < 3; ++k) {
      corners[3 * t + k] = glm::dvec3(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
      // Refused here, before welding, as the text formats refuse them.
      if (!std::isfinite(xyz[3 * k]) || !std::isfinite(xyz[3 * k + 1]) || !std::isfinite(xyz[3 * k + 2]))
        source.refuse("triangle " + std::to_string(t + 1) + " has a corner whose coordinates are not finite numbers");
    }
  }
  return corners;
}

bool keywordIs(std::string_view word, std::string_view keyword)
{
  return word.size() == keyword.size() && std::equal(word.begin(), word.end(), keyword.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == b;
         });
}

// solid NAME / facet normal N N N / outer loop / vertex X Y Z (three times) /
// endloop / endfacet / ... / endsolid NAME, possibly several solids.
class AsciiStl {
public:
  explicit AsciiStl(const MeshSource& source) : source_(source), rest_(text::withoutByteOrderMark(source.bytes)) {}

  std::vector<glm::dvec3> corners()
  {
    std::vector<glm::dvec3> corners;
    enum class Place { Outside, InSolid, InFacet, InLoop, LoopDone } place = Place::Outside;
    int vertices = 0;
    while (!rest_.empty()) {
      line_ = text::nextLine(rest_);
      ++lineNumber_;
      std::string_view words = line_;
      const std::string_view keyword = text::nextToken(words);
      if (keyword.empty()) continue;
      if (place == Place::Outside) {
        if (!keywordIs(keyword, "solid")) fail("expected 'solid'");
        place = Place::InSolid;
      } else if (place == Place::InSolid) {
        if (keywordIs(keyword, "endsolid")) {
          place = Place::Outside;
        } else if (keywordIs(keyword, "facet")) {
          place = Place::InFacet;  // its normal is not used
        } else {
          fail("expected 'facet' or 'endsolid'");
        }
      } else if (place == Place::InFacet) {
        if (!keywordIs(keyword, "outer") || !keywordIs(text::nextToken(words), "loop")) fail("expected 'outer loop'");
        place = Place::InLoop;
        vertices = 0;
      } else if (place == Place::InLoop) {
        if (keywordIs(keyword, "endloop")) {
          if (vertices != 3) fail("a facet with " + std::to_string(vertices) + " vertices (STL facets have 3)");
          place = Place::LoopDone;
        } else if (keywordIs(keyword, "vertex")) {
          if (++vertices > 3) fail("a facet with more than 3 vertices (STL facets have 3)");
          corners.push_back(vertex(words));
        } else {
          fail("expected 'vertex' or 'endloop'");
        }
      } else {  // LoopDone
        if (!keywordIs(keyword, "endfacet")) fail("expected 'endfacet'");
        place = Place::InSolid;
      }
    }
    if (place != Place::Outside) source_.refuse("the file ends before 'endsolid' (is it cut short?)");
    return corners;
  }

private:
  glm::dvec3 vertex(std::string_view words)
  {
    glm::dvec3 p;
    for (int k = 0; k < 3; ++k) {
      const auto value = text::coordinate(text::nextToken(words));
      if (!value) fail(text::notAVertex);
      p[k] = *value;
    }
    if (!text::nextToken(words).empty()) fail("a vertex with more than three coordinates");
    return p;
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    source_.refuse("line " + std::to_string(lineNumber_) + ": " + text::quoted(line_) + ": " + what);
  }

  const MeshSource& source_;
  std::string_view rest_;
  std::string_view line_;
  size_t lineNumber_ = 0;
};

}  // namespace

TriangleMesh readStl(const MeshSource& source)
{
  auto welded = [&](const std::vector<glm::dvec3>& corners) {
    if (corners.size() >= size_t(UINT32_MAX)) source.refuse("more triangle corners than lbmshape can index (2^32 - 1)");
    return weldEqualPositions(corners);
  };
  uint64_t triangles = 0;
  if (looksBinary(source.bytes, triangles)) return welded(readBinaryCorners(source, triangles));
  std::string_view start =
      text::withoutByteOrderMark(source.bytes.substr(0, std::min<size_t>(source.bytes.size(), 512)));
  const std::string_view keyword = text::nextToken(start);
  if (keywordIs(keyword, "solid")) return welded(AsciiStl(source).corners());
  refuseCompressed(source);
  if (keywordIs(keyword, "facet"))
    source.refuse("ASCII STL that does not begin with 'solid' (it begins with 'facet'): add a 'solid' line first");
  if (source.bytes.size() >= headerBytes + countBytes)
    source.refuse("binary STL whose header counts " + std::to_string(triangles) + " triangles (" +
                  std::to_string(headerBytes + countBytes + triangleBytes * triangles) + " bytes), but the file has " +
                  std::to_string(source.bytes.size()) + " bytes");
  source.refuse("not an STL file (too short for binary STL, and it does not begin with 'solid')");
}

}  // namespace lbmshape
