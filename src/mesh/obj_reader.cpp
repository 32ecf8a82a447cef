// Why lbmshape parses OBJ itself: OpenMesh's OBJ reader aborts on a corner
// like "f /1", skips vertex lines it cannot parse (shifting every later index
// onto the wrong vertex), keeps coordinates only as float, and reads a large
// scan at 15-30 MB/s. This reader makes one pass over the mapped file,
// split across threads, and checks every index as it reads it.
//
// Two passes over chunks of whole lines, each chunk on its own thread: the
// first only counts lines and vertex lines, so that the second knows, for
// every chunk, the number of the vertex it starts at. Then relative
// (negative) indices and line numbers in messages come out right without
// any fix-up afterwards.
#include "lbmshape/mesh/obj_reader.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <optional>

#include "lbmshape/core/log.hpp"
#include "lbmshape/mesh/fan_triangulation.hpp"
#include "lbmshape/mesh/text_chunks.hpp"
#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {
namespace {

enum class Statement { Vertex, Face, Other };

// The next statement: a line, joined with the lines after it while it ends
// with a backslash (OBJ's line continuation), without a trailing comment.
// `lines` counts the lines it took; `scratch` holds a joined statement.
std::string_view nextStatement(std::string_view& rest, std::string& scratch, size_t& lines)
{
  std::string_view line = text::nextLine(rest);
  lines = 1;
  if (line.ends_with('\\')) {
    scratch.assign(line.substr(0, line.size() - 1));
    while (!rest.empty()) {
      const std::string_view more = text::nextLine(rest);
      ++lines;
      scratch += ' ';
      if (!more.ends_with('\\')) {
        scratch += more;
        break;
      }
      scratch += more.substr(0, more.size() - 1);
    }
    line = scratch;
  }
  return line.substr(0, line.find('#'));
}

// The kind of a statement and what follows its keyword.
Statement classify(std::string_view line, std::string_view& arguments)
{
  line = text::skipBlanks(line);
  // "vt", "v1", "" ... are not; a bare "v" or "f" is a vertex or face of
  // nothing, refused or skipped as such (passing over a bare "v" put every
  // later face on the wrong vertices).
  if (line.empty() || (line.size() > 1 && !text::isBlank(line[1]))) return Statement::Other;
  arguments = line.substr(std::min<size_t>(2, line.size()));
  if (line[0] == 'v') return Statement::Vertex;
  if (line[0] == 'f') return Statement::Face;
  return Statement::Other;
}

struct ChunkCounts {
  size_t lines = 0;
  size_t vertices = 0;
};

ChunkCounts count(std::string_view chunk)
{
  ChunkCounts counts;
  std::string_view arguments;
  std::string scratch;
  size_t lines = 0;
  while (!chunk.empty()) {
    const std::string_view statement = nextStatement(chunk, scratch, lines);
    counts.lines += lines;
    if (classify(statement, arguments) == Statement::Vertex) ++counts.vertices;
  }
  return counts;
}

struct ChunkResult {
  std::vector<glm::uvec3> triangles;
  // Vertex colours, where a vertex line has them ("v x y z r g b", as
  // MeshLab and scanners write, each in [0, 1]): kept apart, since most
  // files have none.
  std::vector<std::pair<uint32_t, glm::vec3>> colours;
  size_t shortFaces = 0;             // fewer than 3 corners
  std::optional<std::string> fault;  // the chunk's first, with its line number
  std::exception_ptr exception;      // e.g. std::bad_alloc, rethrown after the threads
};

class ChunkParser {
public:
  // Writes the chunk's vertices into `positions` (sized for the whole
  // file's) from index `firstVertex` on.
  ChunkParser(size_t firstLine, size_t firstVertex, std::vector<glm::dvec3>& positions)
      : lineNumber_(firstLine), firstVertex_(firstVertex), positions_(positions)
  {}

  void parse(std::string_view chunk, ChunkResult& result)
  {
    std::string_view arguments;
    std::vector<uint32_t> corners;
    std::string scratch;
    size_t lines = 0;
    while (!chunk.empty() && !result.fault) {
      const std::string_view line = nextStatement(chunk, scratch, lines);
      lineNumber_ += lines;
      switch (classify(line, arguments)) {
      case Statement::Vertex: vertex(line, arguments, result); break;
      case Statement::Face: face(line, arguments, corners, result); break;
      case Statement::Other: other(line, result); break;
      }
    }
  }

private:
  void vertex(std::string_view line, std::string_view arguments, ChunkResult& result)
  {
    glm::dvec3 p;
    for (int k = 0; k < 3; ++k) {
      const auto value = text::coordinate(text::nextToken(arguments));
      if (!value) return fail(result, text::quoted(line) + " is " + text::notAVertex);
      p[k] = *value;
    }
    const auto index = uint32_t(firstVertex_ + verticesRead_++);
    positions_[index] = p;
    // Three more numbers are a colour; one more is the homogeneous w, unused.
    // Anything else is a damaged line: a lost line end ("v 1 0 0\rv 9 9 9"
    // with a lone carriage return) put one vertex's numbers on another's
    // line, and every later face on the wrong vertices.
    double extra[3];
    int extras = 0;
    for (std::string_view token = text::nextToken(arguments); !token.empty(); token = text::nextToken(arguments)) {
      const auto value = text::coordinate(token);
      if (!value || extras == 3) return fail(result, text::quoted(line) + notOnlyAVertex(line));
      extra[extras++] = *value;
    }
    if (extras == 2) return fail(result, text::quoted(line) + notOnlyAVertex(line));
    if (extras == 3)
      result.colours.emplace_back(
          index, glm::vec3(float(std::clamp(extra[0], 0.0, 1.0)), float(std::clamp(extra[1], 0.0, 1.0)),
                           float(std::clamp(extra[2], 0.0, 1.0))));
  }

  static std::string notOnlyAVertex(std::string_view line)
  {
    return std::string(
               " is not a vertex: after its three coordinates come a w, or a colour's three numbers, and "
               "nothing else") +
           (line.find('\r') != std::string_view::npos
                ? " (a carriage return inside the line: are lines ended by CR alone?)"
                : "");
  }

  // What follows a corner's vertex number: "/vt", "/vt/vn" or "//vn", each
  // number an integer ("1/" and "1//" pass: some exporters write them).
  static bool isCornerTail(std::string_view tail)
  {
    for (int fields = 0; !tail.empty(); ++fields) {
      if (fields == 2) return false;  // a third slash
      tail.remove_prefix(1);
      const std::string_view field = tail.substr(0, tail.find('/'));
      if (!field.empty() && !text::integer(field)) return false;
      tail.remove_prefix(field.size());
    }
    return true;
  }

  void face(std::string_view line, std::string_view arguments, std::vector<uint32_t>& corners, ChunkResult& result)
  {
    corners.clear();
    // Vertices defined before this line: what a relative index counts back from.
    const size_t before = firstVertex_ + verticesRead_;
    for (std::string_view token = text::nextToken(arguments); !token.empty(); token = text::nextToken(arguments)) {
      const size_t slash = token.find('/');
      const auto index = text::integer(token.substr(0, slash));
      if (!index) return fail(result, text::quoted(line) + ": corner " + text::quoted(token) + " has no vertex number");
      if (slash != std::string_view::npos && !isCornerTail(token.substr(slash)))
        return fail(result, text::quoted(line) + ": corner " + text::quoted(token) +
                                " is not of the form v, v/vt, v/vt/vn or v//vn");
      int64_t zeroBased = *index > 0 ? *index - 1 : int64_t(before) + *index;
      if (*index == 0) return fail(result, text::quoted(line) + ": vertex numbers start at 1, not 0");
      if (*index < 0 && zeroBased < 0)
        return fail(result, text::quoted(line) + " refers to vertex " + std::to_string(*index) + ", but only " +
                                std::to_string(before) + " vertices come before it");
      if (zeroBased >= int64_t(positions_.size()))
        return fail(result, text::quoted(line) + " refers to vertex number " + std::to_string(*index) +
                                ", but there are only " + std::to_string(positions_.size()) + " vertices");
      corners.push_back(uint32_t(zeroBased));
    }
    if (corners.size() < 3) {
      ++result.shortFaces;
      return;
    }
    appendFan(corners, result.triangles);
  }

  // Statements OBJ has and lbmshape needs not (vt, g, usemtl, ...) are
  // passed over; a keyword with a byte that no OBJ keyword has (a NUL, a
  // no-break space after "v") is a damaged line, and passing over a damaged
  // vertex line would put every later face on the wrong vertices.
  void other(std::string_view line, ChunkResult& result)
  {
    std::string_view rest = text::skipBlanks(line);
    const std::string_view keyword = text::nextToken(rest);
    for (const char c : keyword) {
      const auto byte = static_cast<unsigned char>(c);
      if (byte < 0x21 || byte > 0x7e) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", byte);
        return fail(result, text::quoted(line) + " is not an OBJ statement: its keyword holds the byte " + hex +
                                " (a damaged or binary file)");
      }
    }
  }

  void fail(ChunkResult& result, const std::string& what)
  {
    result.fault = "line " + std::to_string(lineNumber_) + ": " + what;
  }

  size_t lineNumber_;  // of the (last) line being parsed, from 1
  size_t firstVertex_;
  size_t verticesRead_ = 0;
  std::vector<glm::dvec3>& positions_;
};

// Chunks of whole statements: a chunk that ends inside a continued line
// takes the next chunk in too.
std::vector<std::string_view> statementChunks(std::string_view text)
{
  std::vector<std::string_view> chunks;
  for (std::string_view chunk : splitIntoLineChunks(text)) {
    if (!chunks.empty() && (chunks.back().ends_with("\\\n") || chunks.back().ends_with("\\\r\n")))
      chunks.back() = std::string_view(chunks.back().data(), chunks.back().size() + chunk.size());
    else
      chunks.push_back(chunk);
  }
  return chunks;
}

}  // namespace

TriangleMesh readObj(const MeshSource& source)
{
  const std::vector<std::string_view> chunks = statementChunks(text::withoutByteOrderMark(source.bytes));
  const size_t n = chunks.size();

  std::vector<ChunkCounts> counts(n);
#pragma omp parallel for schedule(dynamic, 1)
  for (size_t c = 0; c < n; ++c) counts[c] = count(chunks[c]);  // allocates nothing: cannot throw

  std::vector<size_t> firstLine(n, 0), firstVertex(n, 0);
  size_t vertices = 0;
  for (size_t c = 0; c < n; ++c) {
    firstLine[c] = c == 0 ? 0 : firstLine[c - 1] + counts[c - 1].lines;
    firstVertex[c] = vertices;
    vertices += counts[c].vertices;
  }
  if (vertices > size_t(UINT32_MAX))
    source.refuse("it has " + std::to_string(vertices) + " vertices, more than the 2^32 - 1 lbmshape can index");

  TriangleMesh mesh;
  mesh.positions.resize(vertices);
  std::vector<ChunkResult> results(n);
#pragma omp parallel for schedule(dynamic, 1)
  for (size_t c = 0; c < n; ++c) {
    try {
      ChunkParser(firstLine[c], firstVertex[c], mesh.positions).parse(chunks[c], results[c]);
    } catch (...) {
      results[c].exception = std::current_exception();
    }
  }
  for (const ChunkResult& result : results) {  // the first fault in file order
    if (result.exception) std::rethrow_exception(result.exception);
    if (result.fault) source.refuse(*result.fault);
  }

  size_t triangles = 0, shortFaces = 0;
  for (const ChunkResult& result : results) triangles += result.triangles.size(), shortFaces += result.shortFaces;
  mesh.triangles.reserve(triangles);
  for (ChunkResult& result : results) {
    mesh.triangles.insert(mesh.triangles.end(), result.triangles.begin(), result.triangles.end());
    result.triangles = {};  // freed as soon as it is copied
  }
  for (const ChunkResult& result : results)
    for (const auto& [vertex, colour] : result.colours) {
      if (mesh.colours.empty()) mesh.colours.assign(vertices, glm::vec3(1.0f));  // white where a vertex has none
      mesh.colours[vertex] = colour;
    }
  warnOfShortFaces(source.name, shortFaces);
  return mesh;
}

}  // namespace lbmshape
