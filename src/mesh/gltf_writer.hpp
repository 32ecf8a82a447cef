// A single mesh as a glTF 2.0 file (.gltf or .glb).
#pragma once

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/mesh/gltf_compression.hpp"
#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

// One mesh in one node of one scene (see GltfBuilder::addMesh for the
// arrays). Writes into file.temporaryPath(); throws OutputError naming
// file.target().
void writeGltf(const TriangleMesh& mesh, MeshFormat format, const AtomicFile& file,
               GltfCompression compression = GltfCompression::None);

}  // namespace lbmshape
