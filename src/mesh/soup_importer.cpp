#include "mesh/soup_importer.hpp"

#include <algorithm>

namespace lbmshape {

OpenMesh::VertexHandle SoupImporter::add_vertex(const OpenMesh::Vec3f& p)
{
  return add_vertex(OpenMesh::Vec3d(p[0], p[1], p[2]));
}

OpenMesh::VertexHandle SoupImporter::add_vertex(const OpenMesh::Vec3d& p)
{
  mesh_.positions.emplace_back(p[0], p[1], p[2]);
  return OpenMesh::VertexHandle(int(mesh_.positions.size() - 1));
}

OpenMesh::VertexHandle SoupImporter::add_vertex() { return add_vertex(OpenMesh::Vec3d(0.0, 0.0, 0.0)); }

void SoupImporter::set_point(OpenMesh::VertexHandle vertex, const OpenMesh::Vec3f& p)
{
  if (vertex.is_valid() && size_t(vertex.idx()) < mesh_.positions.size())
    mesh_.positions[size_t(vertex.idx())] = glm::dvec3(p[0], p[1], p[2]);
}

OpenMesh::FaceHandle SoupImporter::add_face(const VHandles& indices)
{
  const size_t face = facesSeen_++;
  if (indices.size() < 3) {
    ++facesWithTooFewVertices_;
    return OpenMesh::FaceHandle();
  }
  for (const auto& v : indices)
    if (!v.is_valid() || size_t(v.idx()) >= mesh_.positions.size()) {
      // Formats count vertices from 0 (PLY, OFF) or from 1 (OBJ); readers
      // hand over 0-based handles, so the message says "number N" from 1.
      if (!badIndex_)
        badIndex_ = "face " + std::to_string(face + 1) + " refers to " +
                    (v.idx() < 0 ? std::string("a vertex before the first one")
                                 : "vertex number " + std::to_string(long(v.idx()) + 1)) +
                    ", but there are only " + std::to_string(mesh_.positions.size()) + " vertices";
      return OpenMesh::FaceHandle();
    }
  // Fan triangulation: exact for the convex polygons files normally hold.
  const OpenMesh::FaceHandle first(int(mesh_.triangles.size()));
  for (size_t k = 1; k + 1 < indices.size(); ++k)
    mesh_.triangles.emplace_back(unsigned(indices[0].idx()), unsigned(indices[k].idx()),
                                 unsigned(indices[k + 1].idx()));
  return first;
}

void SoupImporter::reserve(unsigned int vertices, unsigned int, unsigned int faces)
{
  // The counts come from file headers, which may be corrupt: cap what is
  // reserved ahead, the vectors still grow as needed.
  constexpr unsigned cap = 1u << 24;
  mesh_.positions.reserve(std::min(vertices, cap));
  mesh_.triangles.reserve(std::min(faces, cap));
}

}  // namespace lbmshape
