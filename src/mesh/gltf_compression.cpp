#include "lbmshape/mesh/gltf_compression.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <meshoptimizer.h>

#include "lbmshape/core/error.hpp"

namespace lbmshape {
namespace {

std::vector<unsigned char> encodeVertices(const void* vertices, size_t count, size_t stride)
{
  std::vector<unsigned char> encoded(meshopt_encodeVertexBufferBound(count, stride));
  encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), vertices, count, stride));
  return encoded;
}

}  // namespace

CompressedMesh compressMesh(const TriangleMesh& mesh, const std::vector<float>& unitNormals,
                            const std::vector<float>& linearColours)
{
  CompressedMesh out;
  out.indexCount = 3 * mesh.triangleCount();
  std::vector<unsigned int> indices(out.indexCount);
  std::memcpy(indices.data(), mesh.triangles.data(), indices.size() * sizeof(unsigned int));
  const size_t vertices = mesh.vertexCount();
  meshopt_optimizeVertexCache(indices.data(), indices.data(), indices.size(), vertices);
  std::vector<unsigned int> remap(vertices);
  out.vertexCount = meshopt_optimizeVertexFetchRemap(remap.data(), indices.data(), indices.size(), vertices);
  meshopt_remapIndexBuffer(indices.data(), indices.data(), indices.size(), remap.data());

  // One grid step for all three axes, so that the dequantizing scale is
  // uniform and the normals need no correction.
  glm::dvec3 lo(mesh.positions[mesh.triangles[0].x]), hi = lo;
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) lo = glm::min(lo, mesh.positions[t[k]]), hi = glm::max(hi, mesh.positions[t[k]]);
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  out.translation = lo;
  out.scale = extent > 0.0 ? extent / 65535.0 : 1.0;

  std::vector<uint16_t> positions(4 * out.vertexCount, 0);
  std::vector<int8_t> normals(4 * out.vertexCount, 0);
  const bool coloured = linearColours.size() == 3 * vertices;
  std::vector<uint8_t> colours(coloured ? 4 * out.vertexCount : 0, 255);
  out.positionMin = glm::u16vec3(65535), out.positionMax = glm::u16vec3(0);
  for (size_t v = 0; v < vertices; ++v) {
    const unsigned int to = remap[v];
    if (to == ~0u) continue;  // used by no triangle
    for (int k = 0; k < 3; ++k) {
      const double q = std::round((mesh.positions[v][k] - lo[k]) / out.scale);
      const auto value = uint16_t(std::clamp(q, 0.0, 65535.0));
      positions[4 * to + k] = value;
      out.positionMin[k] = std::min(out.positionMin[k], value);
      out.positionMax[k] = std::max(out.positionMax[k], value);
      normals[4 * to + k] = int8_t(std::lround(std::clamp(unitNormals[3 * v + k], -1.0f, 1.0f) * 127.0f));
      if (coloured)
        colours[4 * to + k] = uint8_t(std::lround(std::clamp(linearColours[3 * v + k], 0.0f, 1.0f) * 255.0f));
    }
  }
  out.positions = encodeVertices(positions.data(), out.vertexCount, CompressedMesh::positionStride);
  out.normals = encodeVertices(normals.data(), out.vertexCount, CompressedMesh::normalStride);
  if (coloured) out.colours = encodeVertices(colours.data(), out.vertexCount, CompressedMesh::colourStride);

  // 16-bit indices up to 65534: 65535 is the primitive restart of WebGL2
  // and Vulkan, which glTF forbids as an index of that type.
  out.indexSize = out.vertexCount <= 65535 ? 2 : 4;
  out.indices.resize(meshopt_encodeIndexBufferBound(indices.size(), out.vertexCount));
  out.indices.resize(meshopt_encodeIndexBuffer(out.indices.data(), out.indices.size(), indices.data(), indices.size()));
  if (out.positions.empty() || out.normals.empty() || out.indices.empty())
    throw OutputError("meshoptimizer could not encode a mesh of " + std::to_string(mesh.triangleCount()) +
                      " triangles");
  return out;
}

}  // namespace lbmshape
