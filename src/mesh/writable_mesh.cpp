#include "lbmshape/mesh/writable_mesh.hpp"

#include <algorithm>
#include <limits>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/number_text.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/mesh/single_precision.hpp"
#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {
namespace {

// A hundredth of an edge: the triangles keep their shape and normals.
bool roundingKeepsTheShape(double rounding, double edge) { return rounding <= 0.01 * edge; }

// The formats to suggest when single precision would collapse a mesh's
// triangles: OBJ keeps doubles; glTF stores single precision about the
// mesh's centre, which keeps a mesh far from the origin but not one whose
// edges are themselves too small for single precision.
std::string formatsThatKeep(const TriangleMesh& mesh, CoordinatePrecision precision, double edge)
{
  const bool aboutItsCentreHolds =
      precision != CoordinatePrecision::SingleAboutAnOrigin &&
      roundingKeepsTheShape(singlePrecisionRounding(mesh, singlePrecisionOrigin(mesh)), edge);
  return aboutItsCentreHolds ? ".obj or .glb, which keep them" : ".obj, which keeps doubles";
}

void requireSinglePrecisionHolds(const TriangleMesh& mesh, const std::filesystem::path& path, const std::string& prefix,
                                 CoordinatePrecision precision)
{
  const glm::dvec3 origin =
      precision == CoordinatePrecision::SingleAboutAnOrigin ? singlePrecisionOrigin(mesh) : glm::dvec3(0.0);
  const double largest = double(std::numeric_limits<float>::max());
  for (const auto& p : mesh.positions)
    if (glm::any(glm::greaterThan(glm::abs(p - origin), glm::dvec3(largest))))
      throw OutputError(prefix + " has a coordinate beyond single precision (" + numberText(largest) + "), which " +
                        path.extension().string() + " stores; write .obj, which keeps doubles");
  const double rounding = singlePrecisionRounding(mesh, origin), edge = meanEdgeLength(mesh);
  if (!roundingKeepsTheShape(rounding, edge)) {
    const Bounds box = bounds(mesh);
    const glm::dvec3 corner = glm::max(glm::abs(box.min), glm::abs(box.max));
    const double farthest = std::max({corner.x, corner.y, corner.z});
    throw OutputError(prefix + " lies up to " + threeSignificantDigits(farthest) + " from the origin, where " +
                      path.extension().string() + "'s single-precision coordinates would move its vertices by up to " +
                      threeSignificantDigits(rounding) + ", more than a hundredth of its edges (" +
                      threeSignificantDigits(edge) + " on average), and its triangles would collapse; write " +
                      formatsThatKeep(mesh, precision, edge));
  }
}

}  // namespace

void requireWritable(const TriangleMesh& mesh, const std::filesystem::path& path, const std::string& what,
                     EmptyMesh empty, CoordinatePrecision precision)
{
  const std::string prefix = "cannot write " + path.string() + ": " + what;
  if (mesh.triangles.empty() && empty == EmptyMesh::Refused) throw OutputError(prefix + " has no triangles");
  for (const auto& t : mesh.triangles)
    if (t[0] >= mesh.positions.size() || t[1] >= mesh.positions.size() || t[2] >= mesh.positions.size())
      throw OutputError(prefix + " has a triangle that refers to a vertex it does not have");
  for (const auto& p : mesh.positions) {
    if (!isFinite(p)) throw OutputError(prefix + " has a coordinate that is not a finite number");
    // Even where the format keeps doubles (OBJ): lbmshape's readers take
    // nothing beyond their largest coordinate, so such a file (noise of
    // --sigma 1e200) could not be read back.
    if (glm::any(glm::greaterThan(glm::abs(p), glm::dvec3(text::largestCoordinate))))
      throw OutputError(prefix + " has a coordinate beyond " + threeSignificantDigits(text::largestCoordinate) +
                        ", single precision's largest, which lbmshape could not read back");
  }
  if (precision != CoordinatePrecision::Double) requireSinglePrecisionHolds(mesh, path, prefix, precision);
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
    throw OutputError(prefix + " has " + std::to_string(mesh.normals.size()) + " normals for " +
                      std::to_string(mesh.positions.size()) + " vertices");
  if (!mesh.colours.empty() && mesh.colours.size() != mesh.positions.size())
    throw OutputError(prefix + " has " + std::to_string(mesh.colours.size()) + " colours for " +
                      std::to_string(mesh.positions.size()) + " vertices");
}

}  // namespace lbmshape
