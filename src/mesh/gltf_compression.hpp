// The meshes of a compressed glTF file (--compress): quantized as
// KHR_mesh_quantization allows, then encoded with meshoptimizer's codecs for
// EXT_meshopt_compression. Three.js (with its meshopt decoder), Babylon.js
// and gltfpack read them (Blender's importer not yet); most files shrink
// about 5 times.
//
// Positions become unsigned 16-bit integers on a grid spanning the mesh's
// largest extent (an error of at most 1/131070 of it, a few thousandths of a
// voxel at the resolutions lbmshape runs), which a node's translation and
// uniform scale map back; normals become signed 8-bit normalized integers
// (within half a degree). Vertices and triangles are reordered for the
// codecs and the GPU's vertex cache; unused vertices are dropped.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

inline constexpr const char* meshoptExtension = "EXT_meshopt_compression";
inline constexpr const char* quantizationExtension = "KHR_mesh_quantization";

// How the meshes' arrays of a glTF file are stored: float positions and
// normals with uint32 indices, or quantized and meshopt-encoded (below),
// which only .glb files hold (--compress).
enum class GltfCompression { None, Meshopt };

struct CompressedMesh {
  static constexpr uint32_t positionStride = 8;  // x, y, z uint16 and padding: glTF aligns attributes to 4 bytes
  static constexpr uint32_t normalStride = 4;    // x, y, z int8 and padding
  static constexpr uint32_t colourStride = 4;    // linear RGBA uint8 (COLOR_0, normalized)
  size_t vertexCount = 0, indexCount = 0;
  uint32_t indexSize = 4;                                           // 2 where the vertices fit 16-bit indices
  std::vector<unsigned char> positions, normals, colours, indices;  // as the codecs encode them; colours may be empty
  glm::u16vec3 positionMin{0}, positionMax{0};                      // of the quantized positions (glTF requires them)
  // A quantized position q stands for translation + scale * q.
  glm::dvec3 translation{0.0};
  double scale = 1.0;
};

// `unitNormals`: three floats per vertex, each triple of unit length;
// `linearColours`: three floats per vertex in [0, 1], or none.
CompressedMesh compressMesh(const TriangleMesh& mesh, const std::vector<float>& unitNormals,
                            const std::vector<float>& linearColours = {});

}  // namespace lbmshape
