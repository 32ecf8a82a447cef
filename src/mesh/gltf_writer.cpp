#include "lbmshape/mesh/gltf_writer.hpp"

#include "lbmshape/mesh/gltf_builder.hpp"

namespace lbmshape {

void writeGltf(const TriangleMesh& mesh, MeshFormat format, const AtomicFile& file, GltfCompression compression)
{
  GltfBuilder builder(compression);
  const std::string name = file.target().stem().string();
  builder.addNode(builder.addMesh(mesh, name), name);
  saveGltf(builder.model(), format, file);
}

}  // namespace lbmshape
