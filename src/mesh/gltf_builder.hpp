// Assembles the glTF files lbmshape writes: one buffer that holds every
// array, meshes of triangles with positions and unit normals, and the nodes
// and animation that show them. Files are written through saveGltf().
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/atomic_file.hpp"
#include "mesh/mesh_format.hpp"
#include "mesh/triangle_mesh.hpp"

namespace lbmshape {

class GltfBuilder {
public:
  GltfBuilder();  // asset version 2.0, generator "lbmshape <version>"

  // A mesh of one TRIANGLES primitive: POSITION (float, with min/max),
  // NORMAL (float, unit length: the mesh's own normals where they are
  // usable, else area-weighted ones), uint32 indices. Returns its index, or
  // -1 for a mesh without triangles: glTF has no empty meshes (nor empty
  // accessors), so nothing is added and the node stays without a mesh.
  int addMesh(const TriangleMesh& mesh, const std::string& name);
  // A node showing `mesh` (none if -1), made a root of the (single) scene;
  // returns its index.
  int addNode(int mesh, const std::string& name, std::vector<double> scale = {});
  // A float accessor over `values` (count x components of `type`), in its
  // own buffer view; min/max are filled in when `withBounds`.
  int addFloatAccessor(const std::vector<float>& values, int type, bool withBounds, int target = 0);

  tinygltf::Model& model() { return model_; }

private:
  int addBufferView(const void* data, size_t bytes, int target);

  tinygltf::Model model_;
};

// Writes the model to file.temporaryPath() as a .glb, or as a .gltf with its
// buffer embedded (a data URI) so the file stands alone; a model that holds no
// data at all is written without a buffer (glTF forbids empty ones). Throws OutputError
// naming file.target().
void saveGltf(const tinygltf::Model& model, MeshFormat format, const AtomicFile& file);

}  // namespace lbmshape
