// An OpenMesh importer that keeps the file as a triangle soup. OpenMesh's own
// mesh types are halfedge structures: they refuse "complex" faces (a third
// face on an edge, inconsistent orientation) and drop them with a warning,
// which would quietly punch holes into non-manifold or self-touching scans.
// This importer takes every face the reader hands over, fan-triangulates
// polygons, and checks indices itself.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/Mesh/BaseKernel.hh>

#include "mesh/triangle_mesh.hpp"

namespace lbmshape {

class SoupImporter : public OpenMesh::IO::BaseImporter {
public:
  // The soup read so far; normals stay empty (lbmshape computes its own).
  TriangleMesh takeMesh() { return std::move(mesh_); }

  // Set when a face referred to a vertex the file does not have: "face 12
  // uses vertex 40 of 38". Such faces are not added.
  const std::optional<std::string>& badIndex() const { return badIndex_; }
  // Faces with fewer than 3 vertices, which the readers pass on as they are.
  size_t facesWithTooFewVertices() const { return facesWithTooFewVertices_; }

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& point) override;
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& point) override;
  OpenMesh::VertexHandle add_vertex() override;
  void set_point(OpenMesh::VertexHandle vertex, const OpenMesh::Vec3f& point) override;
  OpenMesh::FaceHandle add_face(const VHandles& indices) override;
  size_t n_vertices() const override { return mesh_.positions.size(); }
  size_t n_faces() const override { return mesh_.triangles.size(); }
  size_t n_edges() const override { return 0; }
  void reserve(unsigned int vertices, unsigned int, unsigned int faces) override;
  // Readers put custom per-element properties here when asked to (lbmshape
  // never asks); it is there so that no reader meets a null kernel.
  OpenMesh::BaseKernel* kernel() override { return &unusedProperties_; }

  // Topology-building calls come only from OpenMesh's own .om format, and
  // attributes (normals, colours, texture coordinates, status) are not kept.
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override
  {
    return OpenMesh::HalfedgeHandle();
  }
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override { return OpenMesh::FaceHandle(); }
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle, const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle, const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle, int) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}

private:
  TriangleMesh mesh_;
  size_t facesSeen_ = 0;
  size_t facesWithTooFewVertices_ = 0;
  std::optional<std::string> badIndex_;
  OpenMesh::BaseKernel unusedProperties_;
};

}  // namespace lbmshape
