#include "lbmshape/mesh/soup_exporter.hpp"

#include <cmath>

#include <glm/glm.hpp>

namespace lbmshape {

OpenMesh::Vec3d SoupExporter::pointd(OpenMesh::VertexHandle v) const
{
  const glm::dvec3& p = mesh_.positions[size_t(v.idx())];
  return OpenMesh::Vec3d(p.x, p.y, p.z);
}

OpenMesh::Vec3f SoupExporter::colorf(OpenMesh::VertexHandle v) const
{
  if (size_t(v.idx()) >= mesh_.colours.size()) return {0.f, 0.f, 0.f};
  const glm::vec3 c = glm::clamp(mesh_.colours[size_t(v.idx())], 0.f, 1.f);
  return {c.x, c.y, c.z};
}

OpenMesh::Vec3uc SoupExporter::color(OpenMesh::VertexHandle v) const
{
  const OpenMesh::Vec3f c = colorf(v);
  const auto byte = [](float x) { return static_cast<unsigned char>(std::lround(x * 255.f)); };
  return {byte(c[0]), byte(c[1]), byte(c[2])};
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
