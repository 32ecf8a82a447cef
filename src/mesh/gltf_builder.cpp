#include "mesh/gltf_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include "core/error.hpp"
#include "mesh/mesh_geometry.hpp"

namespace lbmshape {
namespace {

// glTF requires NORMAL to be unit length for every vertex, used or not. The
// mesh's own normals are kept where they can be normalised; the others get
// the area-weighted normal, and a vertex that no triangle with area uses gets
// +z, which nothing draws.
std::vector<float> unitNormals(const TriangleMesh& mesh)
{
  std::vector<glm::dvec3> computed;
  auto fallback = [&](size_t i) {
    if (computed.empty()) computed = areaWeightedNormals(mesh);
    return glm::length(computed[i]) > 0.5 ? computed[i] : glm::dvec3(0.0, 0.0, 1.0);
  };
  const bool given = mesh.normals.size() == mesh.positions.size();
  std::vector<float> out;
  out.reserve(3 * mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    glm::dvec3 n = given ? glm::dvec3(mesh.normals[i]) : glm::dvec3(0.0);
    const double length = glm::length(n);
    n = std::isfinite(length) && length > 1e-20 ? n / length : fallback(i);
    out.insert(out.end(), {float(n.x), float(n.y), float(n.z)});
  }
  return out;
}

}  // namespace

GltfBuilder::GltfBuilder()
{
  model_.asset.version = "2.0";
  model_.asset.generator = std::string("lbmshape ") + LBMSHAPE_VERSION;
  model_.buffers.emplace_back();
  model_.scenes.emplace_back();
  model_.defaultScene = 0;
}

int GltfBuilder::addBufferView(const void* data, size_t bytes, int target)
{
  auto& buffer = model_.buffers[0].data;
  buffer.resize((buffer.size() + 3) / 4 * 4, 0);  // every component here is 4 bytes and must be aligned to them
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  const auto* bytesIn = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), bytesIn, bytesIn + bytes);
  model_.bufferViews.push_back(view);
  return int(model_.bufferViews.size() - 1);
}

int GltfBuilder::addFloatAccessor(const std::vector<float>& values, int type, bool withBounds, int target)
{
  const int components = tinygltf::GetNumComponentsInType(uint32_t(type));
  tinygltf::Accessor accessor;
  accessor.bufferView = addBufferView(values.data(), values.size() * sizeof(float), target);
  accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  accessor.type = type;
  accessor.count = values.size() / size_t(components);
  if (withBounds) {
    // The exact float values: validators compare them with the data bit for bit.
    accessor.minValues.assign(size_t(components), std::numeric_limits<double>::infinity());
    accessor.maxValues.assign(size_t(components), -std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < values.size(); ++i) {
      auto& lo = accessor.minValues[i % size_t(components)];
      auto& hi = accessor.maxValues[i % size_t(components)];
      lo = std::min(lo, double(values[i]));
      hi = std::max(hi, double(values[i]));
    }
  }
  model_.accessors.push_back(accessor);
  return int(model_.accessors.size() - 1);
}

int GltfBuilder::addMesh(const TriangleMesh& mesh, const std::string& name)
{
  if (mesh.triangles.empty()) return -1;
  std::vector<float> positions;
  positions.reserve(3 * mesh.positions.size());
  for (const auto& p : mesh.positions) positions.insert(positions.end(), {float(p.x), float(p.y), float(p.z)});

  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] =
      addFloatAccessor(positions, TINYGLTF_TYPE_VEC3, true, TINYGLTF_TARGET_ARRAY_BUFFER);
  primitive.attributes["NORMAL"] =
      addFloatAccessor(unitNormals(mesh), TINYGLTF_TYPE_VEC3, false, TINYGLTF_TARGET_ARRAY_BUFFER);

  static_assert(sizeof(glm::uvec3) == 3 * sizeof(uint32_t), "triangles are stored as packed uint32 triples");
  tinygltf::Accessor indices;
  indices.bufferView = addBufferView(mesh.triangles.data(), mesh.triangles.size() * sizeof(glm::uvec3),
                                     TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  indices.type = TINYGLTF_TYPE_SCALAR;
  indices.count = 3 * mesh.triangles.size();
  model_.accessors.push_back(indices);
  primitive.indices = int(model_.accessors.size() - 1);

  tinygltf::Mesh gltfMesh;
  gltfMesh.name = name;
  gltfMesh.primitives.push_back(primitive);
  model_.meshes.push_back(gltfMesh);
  return int(model_.meshes.size() - 1);
}

int GltfBuilder::addNode(int mesh, const std::string& name, std::vector<double> scale)
{
  tinygltf::Node node;
  node.mesh = mesh;
  node.name = name;
  node.scale = std::move(scale);
  model_.nodes.push_back(node);
  const int index = int(model_.nodes.size() - 1);
  model_.scenes[0].nodes.push_back(index);
  return index;
}

void saveGltf(const tinygltf::Model& model, MeshFormat format, const AtomicFile& file)
{
  const bool binary = format == MeshFormat::Glb;
  std::ofstream out(file.temporaryPath(), std::ios::binary | std::ios::trunc);
  tinygltf::TinyGLTF writer;
  const tinygltf::Model* toWrite = &model;
  tinygltf::Model withoutBuffer;  // a file of no surface has no data
  if (model.buffers.size() == 1 && model.buffers[0].data.empty()) {
    withoutBuffer = model;
    withoutBuffer.buffers.clear();
    toWrite = &withoutBuffer;
  }
  const bool ok = out && writer.WriteGltfSceneToStream(toWrite, out, /*prettyPrint=*/!binary, binary);
  out.close();
  if (!ok || !out)
    throw OutputError("cannot write " + file.target().string() + ": writing the file failed (is the disk full?)");
}

}  // namespace lbmshape
