// Presents a TriangleMesh to OpenMesh's writers as it is. Copying it into an
// OpenMesh TriMesh first would drop every face that mesh's halfedge
// structure refuses (non-manifold edges, flipped neighbours), so a soup goes
// out exactly as it came in.
#pragma once

#include <vector>

#include <OpenMesh/Core/IO/exporter/BaseExporter.hh>
#include <OpenMesh/Core/Mesh/BaseKernel.hh>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

class SoupExporter : public OpenMesh::IO::BaseExporter {
public:
  // `normals`, per vertex, are written where the writer is asked to
  // (Options::VertexNormal); empty for none.
  explicit SoupExporter(const TriangleMesh& mesh, std::vector<glm::vec3> normals = {})
      : mesh_(mesh), normals_(std::move(normals))
  {}

  OpenMesh::Vec3f point(OpenMesh::VertexHandle v) const override { return OpenMesh::Vec3f(pointd(v)); }
  OpenMesh::Vec3d pointd(OpenMesh::VertexHandle v) const override;
  bool is_point_double() const override { return true; }
  unsigned int get_vhandles(OpenMesh::FaceHandle face, std::vector<OpenMesh::VertexHandle>& corners) const override;
  size_t n_vertices() const override { return mesh_.positions.size(); }
  size_t n_faces() const override { return mesh_.triangles.size(); }
  size_t n_edges() const override { return 0; }
  bool is_triangle_mesh() const override { return true; }
  // OpenMesh's PLY writer lists the kernel's custom properties without
  // checking that there is a kernel: this one has none.
  const OpenMesh::BaseKernel* kernel() override { return &noProperties_; }

  bool has_vertex_normals() const override { return !normals_.empty(); }
  OpenMesh::Vec3f normal(OpenMesh::VertexHandle v) const override;
  OpenMesh::Vec3d normald(OpenMesh::VertexHandle v) const override { return OpenMesh::Vec3d(normal(v)); }
  bool is_normal_double() const override { return false; }

  // The mesh's vertex colours (sRGB, 0..1), where it has one a vertex:
  // PLY's red, green and blue bytes, as scanners write them.
  bool has_vertex_colors() const override { return mesh_.colours.size() == mesh_.positions.size(); }
  OpenMesh::Vec3uc color(OpenMesh::VertexHandle v) const override;
  OpenMesh::Vec4uc colorA(OpenMesh::VertexHandle v) const override
  {
    const OpenMesh::Vec3uc c = color(v);
    return {c[0], c[1], c[2], 255};
  }
  OpenMesh::Vec3ui colori(OpenMesh::VertexHandle v) const override
  {
    const OpenMesh::Vec3uc c = color(v);
    return {c[0], c[1], c[2]};
  }
  OpenMesh::Vec4ui colorAi(OpenMesh::VertexHandle v) const override
  {
    const OpenMesh::Vec3uc c = color(v);
    return {c[0], c[1], c[2], 255};
  }
  OpenMesh::Vec3f colorf(OpenMesh::VertexHandle v) const override;
  OpenMesh::Vec4f colorAf(OpenMesh::VertexHandle v) const override
  {
    const OpenMesh::Vec3f c = colorf(v);
    return {c[0], c[1], c[2], 1.f};
  }

  // Nothing else but positions, normals, colours and faces is written.
  OpenMesh::Vec2f texcoord(OpenMesh::VertexHandle) const override { return {0.f, 0.f}; }
  OpenMesh::Vec2f texcoord(OpenMesh::HalfedgeHandle) const override { return {0.f, 0.f}; }
  OpenMesh::Attributes::StatusInfo status(OpenMesh::VertexHandle) const override { return {}; }
  OpenMesh::HalfedgeHandle getHeh(OpenMesh::FaceHandle, OpenMesh::VertexHandle) const override
  {
    return OpenMesh::HalfedgeHandle();
  }
  unsigned int get_face_texcoords(std::vector<OpenMesh::Vec2f>&) const override { return 0; }
  OpenMesh::Vec3f normal(OpenMesh::FaceHandle) const override { return {0.f, 0.f, 0.f}; }
  OpenMesh::Vec3d normald(OpenMesh::FaceHandle) const override { return {0.0, 0.0, 0.0}; }
  OpenMesh::Vec3uc color(OpenMesh::FaceHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4uc colorA(OpenMesh::FaceHandle) const override { return {0, 0, 0, 255}; }
  OpenMesh::Vec3ui colori(OpenMesh::FaceHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4ui colorAi(OpenMesh::FaceHandle) const override { return {0, 0, 0, 255}; }
  OpenMesh::Vec3f colorf(OpenMesh::FaceHandle) const override { return {0.f, 0.f, 0.f}; }
  OpenMesh::Vec4f colorAf(OpenMesh::FaceHandle) const override { return {0.f, 0.f, 0.f, 1.f}; }
  OpenMesh::Attributes::StatusInfo status(OpenMesh::FaceHandle) const override { return {}; }
  OpenMesh::Vec3uc color(OpenMesh::EdgeHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4uc colorA(OpenMesh::EdgeHandle) const override { return {0, 0, 0, 255}; }
  OpenMesh::Vec3ui colori(OpenMesh::EdgeHandle) const override { return {0, 0, 0}; }
  OpenMesh::Vec4ui colorAi(OpenMesh::EdgeHandle) const override { return {0, 0, 0, 255}; }
  OpenMesh::Vec3f colorf(OpenMesh::EdgeHandle) const override { return {0.f, 0.f, 0.f}; }
  OpenMesh::Vec4f colorAf(OpenMesh::EdgeHandle) const override { return {0.f, 0.f, 0.f, 1.f}; }
  OpenMesh::Attributes::StatusInfo status(OpenMesh::EdgeHandle) const override { return {}; }
  OpenMesh::Attributes::StatusInfo status(OpenMesh::HalfedgeHandle) const override { return {}; }
  // Halfedge ids serve only OpenMesh's own .om format, which lbmshape does not write.
  int get_halfedge_id(OpenMesh::VertexHandle) override { return -1; }
  int get_halfedge_id(OpenMesh::FaceHandle) override { return -1; }
  int get_next_halfedge_id(OpenMesh::HalfedgeHandle) override { return -1; }
  int get_to_vertex_id(OpenMesh::HalfedgeHandle) override { return -1; }
  int get_face_id(OpenMesh::HalfedgeHandle) override { return -1; }

private:
  const TriangleMesh& mesh_;
  std::vector<glm::vec3> normals_;
  OpenMesh::BaseKernel noProperties_;
};

}  // namespace lbmshape
