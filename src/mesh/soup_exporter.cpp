#include "lbmshape/mesh/soup_exporter.hpp"

namespace lbmshape {

OpenMesh::Vec3d SoupExporter::pointd(OpenMesh::VertexHandle v) const
{
  const glm::dvec3& p = mesh_.positions[size_t(v.idx())];
  return OpenMesh::Vec3d(p.x, p.y, p.z);
}

OpenMesh::Vec3f SoupExporter::normal(OpenMesh::VertexHandle v) const
{
  if (size_t(v.idx()) >= normals_.size()) return {0.f, 0.f, 0.f};
  const glm::vec3& n = normals_[size_t(v.idx())];
  return OpenMesh::Vec3f(n.x, n.y, n.z);
}

unsigned int SoupExporter::get_vhandles(OpenMesh::FaceHandle face, std::vector<OpenMesh::VertexHandle>& corners) const
{
  const glm::uvec3& t = mesh_.triangles[size_t(face.idx())];
  corners.assign(
      {OpenMesh::VertexHandle(int(t[0])), OpenMesh::VertexHandle(int(t[1])), OpenMesh::VertexHandle(int(t[2]))});
  return 3;
}

}  // namespace lbmshape
