#include "lbmshape/pipeline/parts_check.hpp"

#include <algorithm>
#include <iomanip>
#include <memory>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "lbmshape/core/concurrent_union_find.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"

namespace lbmshape {
namespace {

// The mesh's components (triangles joined through shared vertices), each as
// a soup of its own triangles: enough for its bounds, volume and inside.
std::vector<TriangleMesh> componentsOf(const TriangleMesh& mesh)
{
  ConcurrentUnionFind vertices(mesh.positions.size());
  for (const auto& t : mesh.triangles) {
    vertices.unite(t[0], t[1]);
    vertices.unite(t[0], t[2]);
  }
  const std::vector<uint32_t> root = std::move(vertices).roots();
  std::unordered_map<uint32_t, size_t> componentOfRoot;
  std::vector<TriangleMesh> components;
  for (const auto& t : mesh.triangles) {
    const auto [it, added] = componentOfRoot.try_emplace(root[t[0]], components.size());
    if (added) components.emplace_back();
    TriangleMesh& c = components[it->second];
    const auto first = uint32_t(c.positions.size());
    for (int k = 0; k < 3; ++k) c.positions.push_back(mesh.positions[t[k]]);
    c.triangles.push_back({first, first + 1, first + 2});
  }
  return components;
}

bool overlap(const Bounds& a, const Bounds& b)
{
  return glm::all(glm::lessThanEqual(a.min, b.max)) && glm::all(glm::lessThanEqual(b.min, a.max));
}

}  // namespace

size_t solidParts(const TriangleMesh& mesh)
{
  const std::vector<TriangleMesh> components = componentsOf(mesh);
  if (components.size() <= 1) return components.size();
  std::vector<Bounds> box;
  std::vector<bool> outward;
  for (const TriangleMesh& c : components) {
    box.push_back(bounds(c));
    outward.push_back(areaAndSignedVolume(c).signedVolume > 0.0);
  }
  ConcurrentUnionFind parts(components.size());
  std::vector<std::unique_ptr<TriangleBvh>> inside(components.size());
  for (size_t b = 0; b < components.size(); ++b) {
    if (!outward[b]) continue;  // a cavity is a part of its own
    for (size_t a = 0; a < components.size(); ++a) {
      if (a == b || !outward[a] || !overlap(box[a], box[b]) || parts.find(uint32_t(a)) == parts.find(uint32_t(b)))
        continue;
      if (!inside[b]) inside[b] = std::make_unique<TriangleBvh>(components[b]);
      // Some of a's corners inside b: the two solids share a part of space.
      const size_t stride = std::max<size_t>(1, components[a].positions.size() / 4096);
      for (size_t i = 0; i < components[a].positions.size(); i += stride)
        if (inside[b]->windingNumber(components[a].positions[i]) > 0.5) {
          parts.unite(uint32_t(a), uint32_t(b));
          break;
        }
    }
  }
  const std::vector<uint32_t> partOf = std::move(parts).roots();
  size_t count = 0;  // a set's root is its lowest member
  for (size_t i = 0; i < partOf.size(); ++i) count += partOf[i] == i;
  return count;
}

void warnIfThePartsChanged(const TriangleMesh& wantedMesh, const MeshTopology& wanted, const std::string& wantedName,
                           const MeshTopology& made, const std::string& madeName, double voxel)
{
  if (!wanted.closedManifold || !made.closedManifold || !wanted.genus || !made.genus) return;
  if (wanted.components == made.components && *wanted.genus == *made.genus) return;
  // Overlapping parts become their union: held to that, whatever its genus.
  if (wanted.components > 1) {
    const size_t solid = solidParts(wantedMesh);
    if (solid < wanted.components && made.components == solid) {
      log::verbose(wantedName + "'s " + std::to_string(wanted.components) + " parts overlap: " + madeName +
                   " is their union, " + std::to_string(solid) + (solid == 1 ? " part" : " parts"));
      return;
    }
  }
  const auto parts = [](size_t n) { return std::to_string(n) + (n == 1 ? " part" : " parts"); };
  std::ostringstream m;
  m << madeName << " has " << parts(made.components) << " of genus " << *made.genus << " where " << wantedName
    << " has " << parts(wanted.components) << " of genus " << *wanted.genus
    << ": parts or gaps thinner than about two voxels (voxel " << std::setprecision(3) << voxel
    << ") were cut or closed on this grid; a finer " << nameOf(Parameter::Resolution) << " keeps them";
  log::warning(m.str());
}

}  // namespace lbmshape
