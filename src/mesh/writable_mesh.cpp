#include "mesh/writable_mesh.hpp"

#include <limits>

#include "core/error.hpp"
#include "core/number_text.hpp"
#include "mesh/mesh_geometry.hpp"

namespace lbmshape {

void requireWritable(const TriangleMesh& mesh, const std::filesystem::path& path, const std::string& what,
                     EmptyMesh empty, CoordinatePrecision precision)
{
  const std::string prefix = "cannot write " + path.string() + ": " + what;
  if (mesh.triangles.empty() && empty == EmptyMesh::Refused) throw OutputError(prefix + " has no triangles");
  for (const auto& t : mesh.triangles)
    if (t[0] >= mesh.positions.size() || t[1] >= mesh.positions.size() || t[2] >= mesh.positions.size())
      throw OutputError(prefix + " has a triangle that refers to a vertex it does not have");
  const double largest = precision == CoordinatePrecision::Single ? double(std::numeric_limits<float>::max())
                                                                  : std::numeric_limits<double>::max();
  for (const auto& p : mesh.positions) {
    if (!isFinite(p)) throw OutputError(prefix + " has a coordinate that is not a finite number");
    if (glm::any(glm::greaterThan(glm::abs(p), glm::dvec3(largest))))
      throw OutputError(prefix + " has a coordinate beyond single precision (" + numberText(largest) + "), which " +
                        path.extension().string() + " stores; write .obj, which keeps doubles");
  }
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
    throw OutputError(prefix + " has " + std::to_string(mesh.normals.size()) + " normals for " +
                      std::to_string(mesh.positions.size()) + " vertices");
}

}  // namespace lbmshape
