// Assembles the glTF files lbmshape writes: one buffer that holds every
// array, meshes of triangles with positions and unit normals, and the nodes
// and animation that show them. Files are written through saveGltf().
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include <tiny_gltf.h>

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/mesh/gltf_compression.hpp"
#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

class GltfBuilder {
public:
  // Asset version 2.0, generator "lbmshape <version>".
  explicit GltfBuilder(GltfCompression compression = GltfCompression::None);

  // A mesh of one TRIANGLES primitive: POSITION (float, with min/max; about
  // the mesh's centre where it lies far from the origin for its size),
  // NORMAL (float, unit length: the mesh's own normals where they are
  // usable, else area-weighted ones), uint32 indices. Returns its index, or
  // -1 for a mesh without triangles: glTF has no empty meshes (nor empty
  // accessors), so nothing is added and the node stays without a mesh.
  // `aboutItsCentre` stores every mesh about its centre, near the origin
  // too: an animation's hidden frames (scale 0) then shrink to a point
  // within themselves, not to the origin, which a viewer framing the scene
  // took in (a morph 10 units from the origin was framed from 0 to 10.5).
  int addMesh(const TriangleMesh& mesh, const std::string& name, bool aboutItsCentre = false);
  // A node showing `mesh` (none if -1), made a root of the (single) scene;
  // returns its index. A mesh stored about its centre (single_precision.hpp)
  // or quantized gets that centre (the quantization's offset) as the node's
  // translation, and a quantized one hangs from a child node whose scale
  // undoes the quantization's step. `scale` (and an animation of it) is
  // then about that centre: 1 shows the mesh where it is, 0 shrinks it to a
  // point within it rather than to the origin.
  int addNode(int mesh, const std::string& name, std::vector<double> scale = {});
  // A float accessor over `values` (count x components of `type`), in its
  // own buffer view; min/max are filled in when `withBounds`.
  int addFloatAccessor(const std::vector<float>& values, int type, bool withBounds, int target = 0);

  tinygltf::Model& model() { return model_; }

  // The bytes added to the buffer since the last call, handed over: a
  // writer that streams the buffer to its file as it grows (GltfAnimation).
  // The views keep their offsets in the whole buffer; the model then holds
  // only what was added since, so saveGltf() cannot write it.
  std::vector<unsigned char> takeBufferData();
  // The whole buffer's length, taken bytes included.
  size_t bufferBytes() const { return taken_ + model_.buffers[0].data.size(); }

private:
  int addBufferView(const void* data, size_t bytes, int target);
  int addAccessor(const tinygltf::Accessor& accessor);
  int addOnePrimitiveMesh(const tinygltf::Primitive& primitive, const std::string& name);
  int addCompressedMesh(const TriangleMesh& mesh, const std::string& name);
  // A buffer view of `count` elements of `stride` bytes, encoded in buffer 0
  // and decoded into the fallback buffer 1 (which the file does not hold).
  int addEncodedView(const std::vector<unsigned char>& encoded, size_t count, uint32_t stride, const char* mode,
                     int target);

  tinygltf::Model model_;
  GltfCompression compression_;
  size_t decodedBytes_ = 0;  // of the fallback buffer
  size_t taken_ = 0;         // bytes of buffer 0 handed over (takeBufferData)
  // The translation and scale that place a mesh's stored positions, by mesh:
  // a compressed one's dequantization, or a far one's centre.
  std::map<int, std::pair<glm::dvec3, double>> placements_;
};

// Writes the model to file.temporaryPath() as a .glb, or as a .gltf with its
// buffer embedded (a data URI) so the file stands alone; a model that holds no
// data at all is written without a buffer (glTF forbids empty ones). A
// compressed model is written as .glb only. Throws OutputError naming
// file.target(). The model is only borrowed: a .glb's buffer is written from
// where it lies, moved out of the model meanwhile and back before return.
void saveGltf(tinygltf::Model& model, MeshFormat format, const AtomicFile& file);

// The JSON chunk of a .glb whose binary chunk holds the model's buffer of
// `bufferBytes` bytes, when the model itself holds none of them (its buffer
// streamed to the file as it grew: GltfAnimation); with 0 bytes, a file
// without a buffer. Uncompressed models only (std::logic_error otherwise).
std::string plainGlbJson(const tinygltf::Model& model, size_t bufferBytes);

}  // namespace lbmshape
