#include "lbmshape/mesh/obj_writer.hpp"

#include <charconv>
#include <fstream>

#include "lbmshape/core/error.hpp"

namespace lbmshape {
namespace {

template <class Vector>
void appendNumbers(std::string& line, const Vector& v)
{
  char number[32];
  for (int k = 0; k < 3; ++k) {
    auto end = std::to_chars(number, number + sizeof number, v[k]).ptr;  // shortest exact round trip
    line += ' ';
    line.append(number, end);
  }
}

template <class Vector>
void appendVector(std::string& line, const char* keyword, const Vector& v)
{
  line += keyword;
  appendNumbers(line, v);
  line += '\n';
}

}  // namespace

void writeObj(const TriangleMesh& mesh, const AtomicFile& file)
{
  const bool withNormals = mesh.normals.size() == mesh.positions.size();
  // Vertex colours as MeshLab writes them: "v x y z r g b".
  const bool withColours = mesh.colours.size() == mesh.positions.size();
  std::ofstream out = file.open();
  out << "# lbmshape " << LBMSHAPE_VERSION << ": " << mesh.positions.size() << " vertices, " << mesh.triangles.size()
      << " triangles\n";
  std::string line;
  for (size_t i = 0; i < mesh.positions.size() && out; ++i) {
    line.clear();
    line += 'v';
    appendNumbers(line, mesh.positions[i]);
    if (withColours) appendNumbers(line, mesh.colours[i]);
    line += '\n';
    if (withNormals) appendVector(line, "vn", mesh.normals[i]);
    out << line;
  }
  for (const auto& t : mesh.triangles) {
    if (!out) break;
    out << 'f';
    for (int k = 0; k < 3; ++k) {
      out << ' ' << t[k] + 1;  // OBJ counts from 1
      if (withNormals) out << "//" << t[k] + 1;
    }
    out << '\n';
  }
  out.close();
  if (!out) throw OutputError("cannot write " + file.target().string() + ": " + writeFailure());
}

}  // namespace lbmshape
