#include "lbmshape/mesh/gltf_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/mesh/single_precision.hpp"
#include "lbmshape/mesh/colour_space.hpp"
#include "lbmshape/mesh/glb_container.hpp"
#include "lbmshape/mesh/gltf_compression.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"

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

// COLOR_0 is linear RGB; the mesh keeps colours as shown (sRGB).
std::vector<float> linearColours(const TriangleMesh& mesh)
{
  std::vector<float> out;
  out.reserve(3 * mesh.colours.size());
  for (const glm::vec3& c : mesh.colours)
    for (int k = 0; k < 3; ++k) out.push_back(srgbToLinear(std::clamp(c[k], 0.0f, 1.0f)));
  return out;
}

// tinygltf keeps JSON integers as int.
tinygltf::Value integer(size_t value)
{
  if (value > size_t(std::numeric_limits<int>::max()))
    throw OutputError("a compressed glTF file of more than 2 GB cannot be written; write fewer frames, or without " +
                      nameOf(Parameter::Compression));
  return tinygltf::Value(int(value));
}

// A name as glTF's JSON holds it: UTF-8, with each byte that is not UTF-8
// replaced by U+FFFD (a Latin-1 byte of a file's name: the writer's JSON
// threw on it, after all the work was done).
std::string validUtf8(const std::string& name)
{
  return nlohmann::json::parse(nlohmann::json(name).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace))
      .get<std::string>();
}

}  // namespace

GltfBuilder::GltfBuilder(GltfCompression compression) : compression_(compression)
{
  model_.asset.version = "2.0";
  model_.asset.generator = std::string("lbmshape ") + LBMSHAPE_VERSION;
  model_.buffers.emplace_back();
  model_.scenes.emplace_back();
  model_.defaultScene = 0;
  if (compression_ == GltfCompression::Meshopt) {
    // Buffer 1 is what a decoder makes of the encoded views: declared, never
    // stored (saveGltf sets its length).
    tinygltf::Buffer fallback;
    tinygltf::Value::Object marker;
    marker["fallback"] = tinygltf::Value(true);
    fallback.extensions[meshoptExtension] = tinygltf::Value(marker);
    model_.buffers.push_back(fallback);
    model_.extensionsUsed = {meshoptExtension, quantizationExtension};
    model_.extensionsRequired = {meshoptExtension, quantizationExtension};
  }
}

int GltfBuilder::addEncodedView(const std::vector<unsigned char>& encoded, size_t count, uint32_t stride,
                                const char* mode, int target)
{
  auto& buffer = model_.buffers[0].data;
  buffer.resize(buffer.size() + (4 - bufferBytes() % 4) % 4, 0);
  tinygltf::Value::Object meshopt;
  meshopt["buffer"] = tinygltf::Value(0);
  meshopt["byteOffset"] = integer(bufferBytes());
  meshopt["byteLength"] = integer(encoded.size());
  meshopt["byteStride"] = tinygltf::Value(int(stride));
  meshopt["mode"] = tinygltf::Value(std::string(mode));
  meshopt["count"] = integer(count);
  buffer.insert(buffer.end(), encoded.begin(), encoded.end());

  tinygltf::BufferView view;
  view.buffer = 1;
  view.byteOffset = decodedBytes_;
  view.byteLength = count * stride;
  if (target == TINYGLTF_TARGET_ARRAY_BUFFER) view.byteStride = stride;
  view.target = target;
  view.extensions[meshoptExtension] = tinygltf::Value(meshopt);
  decodedBytes_ = (decodedBytes_ + view.byteLength + 3) / 4 * 4;
  integer(decodedBytes_);
  model_.bufferViews.push_back(view);
  return int(model_.bufferViews.size() - 1);
}

int GltfBuilder::addCompressedMesh(const TriangleMesh& mesh, const std::string& name)
{
  const CompressedMesh c =
      compressMesh(mesh, unitNormals(mesh),
                   mesh.colours.size() == mesh.positions.size() ? linearColours(mesh) : std::vector<float>());
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;

  // One accessor per vertex stream, over its own encoded buffer view.
  const auto attribute = [&](const std::vector<unsigned char>& encoded, uint32_t stride, int componentType,
                             bool normalized, int type) {
    tinygltf::Accessor accessor;
    accessor.bufferView = addEncodedView(encoded, c.vertexCount, stride, "ATTRIBUTES", TINYGLTF_TARGET_ARRAY_BUFFER);
    accessor.componentType = componentType;
    accessor.normalized = normalized;
    accessor.type = type;
    accessor.count = c.vertexCount;
    return accessor;
  };
  tinygltf::Accessor positions = attribute(c.positions, CompressedMesh::positionStride,
                                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, false, TINYGLTF_TYPE_VEC3);
  for (int k = 0; k < 3; ++k)
    positions.minValues.push_back(c.positionMin[k]), positions.maxValues.push_back(c.positionMax[k]);
  primitive.attributes["POSITION"] = addAccessor(positions);
  primitive.attributes["NORMAL"] = addAccessor(
      attribute(c.normals, CompressedMesh::normalStride, TINYGLTF_COMPONENT_TYPE_BYTE, true, TINYGLTF_TYPE_VEC3));
  if (!c.colours.empty())
    primitive.attributes["COLOR_0"] = addAccessor(attribute(
        c.colours, CompressedMesh::colourStride, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, true, TINYGLTF_TYPE_VEC4));

  tinygltf::Accessor indices;
  indices.bufferView =
      addEncodedView(c.indices, c.indexCount, c.indexSize, "TRIANGLES", TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  indices.componentType =
      c.indexSize == 2 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT : TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  indices.type = TINYGLTF_TYPE_SCALAR;
  indices.count = c.indexCount;
  primitive.indices = addAccessor(indices);

  const int index = addOnePrimitiveMesh(primitive, name);
  placements_[index] = {c.translation, c.scale};
  return index;
}

int GltfBuilder::addAccessor(const tinygltf::Accessor& accessor)
{
  model_.accessors.push_back(accessor);
  return int(model_.accessors.size() - 1);
}

int GltfBuilder::addBufferView(const void* data, size_t bytes, int target)
{
  auto& buffer = model_.buffers[0].data;
  // Every component here is 4 bytes and must be aligned to them, in the
  // whole buffer.
  buffer.resize(buffer.size() + (4 - bufferBytes() % 4) % 4, 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = bufferBytes();
  view.byteLength = bytes;
  view.target = target;
  const auto* bytesIn = static_cast<const unsigned char*>(data);
  buffer.insert(buffer.end(), bytesIn, bytesIn + bytes);
  model_.bufferViews.push_back(view);
  return int(model_.bufferViews.size() - 1);
}

std::vector<unsigned char> GltfBuilder::takeBufferData()
{
  std::vector<unsigned char> data;
  data.swap(model_.buffers[0].data);
  taken_ += data.size();
  return data;
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
  return addAccessor(accessor);
}

int GltfBuilder::addMesh(const TriangleMesh& mesh, const std::string& name, bool aboutItsCentre)
{
  if (mesh.triangles.empty()) return -1;
  if (compression_ == GltfCompression::Meshopt) return addCompressedMesh(mesh, name);
  // Far from the origin for its size (or where asked), about its centre,
  // which its node's translation gives back (single_precision.hpp).
  const glm::dvec3 origin = aboutItsCentre ? bounds(mesh).centre() : singlePrecisionOrigin(mesh);
  std::vector<float> positions;
  positions.reserve(3 * mesh.positions.size());
  for (const auto& p : mesh.positions) {
    const glm::dvec3 q = p - origin;
    positions.insert(positions.end(), {float(q.x), float(q.y), float(q.z)});
  }

  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] =
      addFloatAccessor(positions, TINYGLTF_TYPE_VEC3, true, TINYGLTF_TARGET_ARRAY_BUFFER);
  primitive.attributes["NORMAL"] =
      addFloatAccessor(unitNormals(mesh), TINYGLTF_TYPE_VEC3, false, TINYGLTF_TARGET_ARRAY_BUFFER);
  if (mesh.colours.size() == mesh.positions.size())
    primitive.attributes["COLOR_0"] =
        addFloatAccessor(linearColours(mesh), TINYGLTF_TYPE_VEC3, false, TINYGLTF_TARGET_ARRAY_BUFFER);

  static_assert(sizeof(glm::uvec3) == 3 * sizeof(uint32_t), "triangles are stored as packed uint32 triples");
  tinygltf::Accessor indices;
  indices.bufferView = addBufferView(mesh.triangles.data(), mesh.triangles.size() * sizeof(glm::uvec3),
                                     TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  indices.type = TINYGLTF_TYPE_SCALAR;
  indices.count = 3 * mesh.triangles.size();
  primitive.indices = addAccessor(indices);

  const int index = addOnePrimitiveMesh(primitive, name);
  if (origin != glm::dvec3(0.0)) placements_[index] = {origin, 1.0};
  return index;
}

int GltfBuilder::addOnePrimitiveMesh(const tinygltf::Primitive& primitive, const std::string& name)
{
  tinygltf::Mesh gltfMesh;
  gltfMesh.name = validUtf8(name);
  gltfMesh.primitives.push_back(primitive);
  model_.meshes.push_back(gltfMesh);
  return int(model_.meshes.size() - 1);
}

int GltfBuilder::addNode(int mesh, const std::string& name, std::vector<double> scale)
{
  tinygltf::Node node;
  node.name = validUtf8(name);
  node.scale = std::move(scale);
  const auto placed = placements_.find(mesh);
  if (placed == placements_.end()) {
    node.mesh = mesh;
  } else {
    // The translation on the node itself, so that a frame an animation
    // hides (scale 0) shrinks to its own place, not to the origin, where
    // a viewer's "frame all" would take it as part of the scene.
    const auto& [translation, step] = placed->second;
    node.translation = {translation.x, translation.y, translation.z};
    if (step == 1.0) {
      node.mesh = mesh;
    } else {
      tinygltf::Node quantized;  // the compressed positions' step, under the node's own scale
      quantized.mesh = mesh;
      quantized.scale = {step, step, step};
      model_.nodes.push_back(quantized);
      node.children = {int(model_.nodes.size() - 1)};
    }
  }
  model_.nodes.push_back(node);
  const int index = int(model_.nodes.size() - 1);
  model_.scenes[0].nodes.push_back(index);
  return index;
}

namespace {

// A tinygltf value (what the builder keeps extensions in) as JSON.
nlohmann::json toJson(const tinygltf::Value& value)
{
  if (value.IsBool()) return value.Get<bool>();
  if (value.IsInt()) return value.Get<int>();
  if (value.IsNumber()) return value.GetNumberAsDouble();
  if (value.IsString()) return value.Get<std::string>();
  nlohmann::json out = value.IsArray() ? nlohmann::json::array() : nlohmann::json::object();
  if (value.IsArray())
    for (size_t i = 0; i < value.ArrayLen(); ++i) out.push_back(toJson(value.Get(int(i))));
  if (value.IsObject())
    for (const std::string& key : value.Keys()) out[key] = toJson(value.Get(key));
  return out;
}

void addExtensions(nlohmann::json& object, const tinygltf::ExtensionMap& extensions)
{
  for (const auto& [name, value] : extensions) object["extensions"][name] = toJson(value);
}

// tinygltf 2.7 writes no extensions of buffers and buffer views, stores a
// buffer's length as the size of its data, and a GLB's second buffer as a
// data URI: it cannot write EXT_meshopt_compression, whose buffer views
// carry their encoded ranges as an extension and whose fallback buffer has a
// length and no data. So the GLB it wrote is taken apart, those entries
// completed from the model, and the container put together again.
std::string withMeshoptEntries(const std::string& glb, const tinygltf::Model& model, size_t decodedBytes)
{
  const GlbChunks chunks = glbChunks(glb);
  nlohmann::json json = nlohmann::json::parse(chunks.json);
  nlohmann::json& fallback = json.at("buffers").at(1);
  fallback.erase("uri");
  fallback["byteLength"] = decodedBytes;
  addExtensions(fallback, model.buffers[1].extensions);
  for (size_t i = 0; i < model.bufferViews.size(); ++i)
    addExtensions(json.at("bufferViews").at(i), model.bufferViews[i].extensions);
  return glbFile(json.dump(), std::string(chunks.binary));
}

size_t decodedLength(const tinygltf::Model& model)
{
  size_t end = 0;
  for (const tinygltf::BufferView& view : model.bufferViews)
    if (view.buffer == 1) end = std::max(end, view.byteOffset + view.byteLength);
  return std::max<size_t>(end, 4);
}

// A plain .glb written without tinygltf's copy of the buffer (it copies the
// whole buffer before writing it: 171 MB for a 48-frame morph at 256^3,
// most of the 0.41 s that writing its animation took).
bool writePlainGlb(tinygltf::Model& model, std::ostream& out)
{
  struct LentBuffer {
    std::vector<unsigned char>& owner;
    std::vector<unsigned char> data = std::move(owner);
    ~LentBuffer() { owner = std::move(data); }
  } lent{model.buffers[0].data};
  model.buffers[0].data.clear();
  writeGlb(out, plainGlbJson(model, lent.data.size()),
           std::string_view(reinterpret_cast<const char*>(lent.data.data()), lent.data.size()));
  return bool(out);
}

}  // namespace

std::string plainGlbJson(const tinygltf::Model& model, size_t bufferBytes)
{
  if (model.buffers.size() != 1 || !model.buffers[0].data.empty())
    throw std::logic_error("plainGlbJson() is for an uncompressed model whose buffer is elsewhere");
  tinygltf::TinyGLTF writer;
  std::ostringstream glb;
  bool ok = false;
  if (bufferBytes == 0) {
    // No data at all: no buffer either (glTF forbids empty ones).
    tinygltf::Model withoutBuffer = model;  // cheap: it holds no data
    withoutBuffer.buffers.clear();
    ok = writer.WriteGltfSceneToStream(&withoutBuffer, glb, false, true);
  } else {
    ok = writer.WriteGltfSceneToStream(&model, glb, false, true);
  }
  if (!ok) throw std::runtime_error("tinygltf could not serialize the model");
  if (bufferBytes == 0) return std::string(glbChunks(glb.str()).json);
  // tinygltf gave the buffer the length of the data it holds (none).
  nlohmann::json json = nlohmann::json::parse(glbChunks(glb.str()).json);
  json.at("buffers").at(0)["byteLength"] = bufferBytes;
  return json.dump();
}

void saveGltf(tinygltf::Model& model, MeshFormat format, const AtomicFile& file)
{
  const bool binary = format == MeshFormat::Glb;
  if (model.buffers.size() == 2 && !binary)
    throw UsageError(nameOf(Parameter::Compression) + " writes .glb files, not " + file.target().string());
  // A compressed file of no surface is the plain file of no surface: nothing
  // to encode, so neither extension.
  const bool compressed = model.buffers.size() == 2 && !model.buffers[0].data.empty();
  std::ofstream out = file.open();
  tinygltf::TinyGLTF writer;
  const tinygltf::Model* toWrite = &model;
  tinygltf::Model withoutBuffer;  // a file of no surface has no data
  if (model.buffers[0].data.empty()) {
    withoutBuffer = model;
    withoutBuffer.buffers.clear();
    withoutBuffer.extensionsUsed.clear();
    withoutBuffer.extensionsRequired.clear();
    toWrite = &withoutBuffer;
  }
  bool ok = false;
  if (compressed) {
    std::ostringstream glb;
    ok = writer.WriteGltfSceneToStream(toWrite, glb, false, true);
    if (ok) out << withMeshoptEntries(glb.str(), model, decodedLength(model));
  } else if (binary && toWrite == &model) {
    ok = out && writePlainGlb(model, out);
  } else {
    ok = out && writer.WriteGltfSceneToStream(toWrite, out, /*prettyPrint=*/!binary, binary);
  }
  out.close();
  if (!ok || !out) throw OutputError("cannot write " + file.target().string() + ": " + writeFailure());
}

}  // namespace lbmshape
