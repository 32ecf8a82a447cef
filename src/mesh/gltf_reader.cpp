#include "mesh/gltf_reader.hpp"

#include <algorithm>
#include <cstring>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "core/error.hpp"
#include "core/log.hpp"

namespace lbmshape {
namespace {

// Geometry lbmshape would get wrong by ignoring the extension, so refuses.
const std::set<std::string> unsupportedRequiredExtensions = {"KHR_draco_mesh_compression", "EXT_meshopt_compression",
                                                             "KHR_meshopt_compression", "EXT_mesh_gpu_instancing"};

// Images are never needed; this skips their decoding.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*)
{
  return true;
}

// tinygltf's messages span lines and may quote the file's bytes; an error
// message is one line of printable text.
std::string oneLine(std::string text)
{
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  for (char& c : text)
    if (c == '\n')
      c = ';';
    else if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
      c = '?';
  return text;
}

glm::dmat4 localTransform(const tinygltf::Node& node)
{
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glTF stores it
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3)
    m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  if (node.rotation.size() == 4)  // glTF: (x, y, z, w); glm's constructor: (w, x, y, z)
    m = m * glm::mat4_cast(
                glm::normalize(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2])));
  if (node.scale.size() == 3)
    m = m * glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

double readComponent(const unsigned char* p, int componentType, bool normalized)
{
  auto load = [p](auto value) {
    std::memcpy(&value, p, sizeof value);  // buffers need not be aligned for us
    return value;
  };
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load(float());
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return load(double());
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load(uint32_t());
    case TINYGLTF_COMPONENT_TYPE_INT: return load(int32_t());
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return normalized ? load(uint16_t()) / 65535.0 : load(uint16_t());
    case TINYGLTF_COMPONENT_TYPE_SHORT: return normalized ? std::max(load(int16_t()) / 32767.0, -1.0) : load(int16_t());
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? load(uint8_t()) / 255.0 : load(uint8_t());
    case TINYGLTF_COMPONENT_TYPE_BYTE: return normalized ? std::max(load(int8_t()) / 127.0, -1.0) : load(int8_t());
  }
  return 0.0;
}

class SoupBuilder {
public:
  SoupBuilder(const tinygltf::Model& model, std::string prefix) : model_(model), prefix_(std::move(prefix)) {}

  void addNode(int index, const glm::dmat4& parent, std::vector<int>& path)
  {
    if (index < 0 || size_t(index) >= model_.nodes.size())
      fail("a scene or node refers to node " + std::to_string(index) + ", which does not exist");
    if (std::find(path.begin(), path.end(), index) != path.end())
      fail("node " + std::to_string(index) + " is its own ancestor");
    const tinygltf::Node& node = model_.nodes[size_t(index)];
    const glm::dmat4 world = parent * localTransform(node);
    if (node.mesh >= 0) addMesh(node.mesh, world);
    path.push_back(index);
    for (int child : node.children) addNode(child, world, path);
    path.pop_back();
  }

  TriangleMesh take() { return std::move(mesh_); }

private:
  [[noreturn]] void fail(const std::string& why) const { throw InputError(prefix_ + why); }

  void addMesh(int index, const glm::dmat4& world)
  {
    if (size_t(index) >= model_.meshes.size())
      fail("a node refers to mesh " + std::to_string(index) + ", which does not exist");
    const auto& primitives = model_.meshes[size_t(index)].primitives;
    for (size_t p = 0; p < primitives.size(); ++p)
      addPrimitive(primitives[p], "mesh " + std::to_string(index) + " primitive " + std::to_string(p), world);
  }

  void addPrimitive(const tinygltf::Primitive& primitive, const std::string& name, const glm::dmat4& world)
  {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      log::verbose(prefix_ + "skipped " + name + ": points or lines, not triangles");
      return;
    }
    auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) {
      log::verbose(prefix_ + "skipped " + name + ": it has no POSITION attribute");
      return;
    }
    const std::vector<double> positions = readAccessor(position->second, TINYGLTF_TYPE_VEC3, name + " POSITION");
    const size_t vertexCount = positions.size() / 3;
    std::vector<uint32_t> order;
    if (primitive.indices >= 0) {
      std::vector<double> indices = readAccessor(primitive.indices, TINYGLTF_TYPE_SCALAR, name + " indices");
      order.reserve(indices.size());
      for (double i : indices) {
        if (i < 0 || i >= double(vertexCount))
          fail(name + " has index " + std::to_string(int64_t(i)) + " but only " + std::to_string(vertexCount) +
               " vertices");
        order.push_back(uint32_t(i));
      }
    } else {
      order.resize(vertexCount);
      for (size_t i = 0; i < vertexCount; ++i) order[i] = uint32_t(i);
    }

    const auto base = uint32_t(mesh_.positions.size());
    for (size_t i = 0; i < vertexCount; ++i)
      mesh_.positions.emplace_back(world *
                                   glm::dvec4(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2], 1.0));
    // A mirroring transform turns counter-clockwise faces clockwise (glTF
    // spec, 3.7.4); swapping two corners keeps them facing outwards.
    const bool mirrored = glm::determinant(world) < 0;
    auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
      if (mirrored) std::swap(b, c);
      mesh_.triangles.emplace_back(base + a, base + b, base + c);
    };
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      for (size_t i = 0; i + 2 < order.size(); i += 3) add(order[i], order[i + 1], order[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (size_t i = 0; i + 2 < order.size(); ++i)  // every other triangle reversed to keep one winding
        i % 2 == 0 ? add(order[i], order[i + 1], order[i + 2]) : add(order[i + 1], order[i], order[i + 2]);
    } else {
      for (size_t i = 1; i + 1 < order.size(); ++i) add(order[i], order[i + 1], order[0]);
    }
  }

  // The accessor's elements as doubles (count x components), with sparse
  // substitution; refuses any read outside the buffers.
  std::vector<double> readAccessor(int index, int type, const std::string& what) const
  {
    if (index < 0 || size_t(index) >= model_.accessors.size())
      fail(what + " refers to accessor " + std::to_string(index) + ", which does not exist");
    const tinygltf::Accessor& accessor = model_.accessors[size_t(index)];
    const int components = tinygltf::GetNumComponentsInType(uint32_t(accessor.type));
    const int componentSize = tinygltf::GetComponentSizeInBytes(uint32_t(accessor.componentType));
    if (accessor.type != type || componentSize <= 0)
      fail(what + " (accessor " + std::to_string(index) + ") has the wrong type");
    std::vector<double> values(accessor.count * size_t(components), 0.0);
    if (accessor.bufferView >= 0) {
      const unsigned char* data = viewData(accessor.bufferView, what);
      const auto& view = model_.bufferViews[size_t(accessor.bufferView)];
      const size_t elementSize = size_t(componentSize) * size_t(components);
      const size_t stride = view.byteStride ? view.byteStride : elementSize;
      if (accessor.count > 0 && accessor.byteOffset + stride * (accessor.count - 1) + elementSize > view.byteLength)
        fail(what + " (accessor " + std::to_string(index) + ") reads past the end of its buffer view");
      for (size_t i = 0; i < accessor.count; ++i)
        for (int c = 0; c < components; ++c)
          values[i * size_t(components) + size_t(c)] =
              readComponent(data + accessor.byteOffset + i * stride + size_t(c * componentSize), accessor.componentType,
                            accessor.normalized);
    }
    if (accessor.sparse.isSparse) applySparse(accessor, components, componentSize, values, what);
    return values;
  }

  void applySparse(const tinygltf::Accessor& accessor, int components, int componentSize, std::vector<double>& values,
                   const std::string& what) const
  {
    const auto& sparse = accessor.sparse;
    const int indexSize = tinygltf::GetComponentSizeInBytes(uint32_t(sparse.indices.componentType));
    const size_t count = size_t(std::max(sparse.count, 0));
    if (indexSize <= 0) fail(what + " has sparse indices of an unknown type");
    const unsigned char* indices = viewData(sparse.indices.bufferView, what);
    const unsigned char* substitutes = viewData(sparse.values.bufferView, what);
    const size_t elementSize = size_t(componentSize) * size_t(components);
    if (size_t(sparse.indices.byteOffset) + count * size_t(indexSize) >
            model_.bufferViews[size_t(sparse.indices.bufferView)].byteLength ||
        size_t(sparse.values.byteOffset) + count * elementSize >
            model_.bufferViews[size_t(sparse.values.bufferView)].byteLength)
      fail(what + " has sparse data past the end of its buffer view");
    for (size_t k = 0; k < count; ++k) {
      const double target = readComponent(indices + sparse.indices.byteOffset + k * size_t(indexSize),
                                          sparse.indices.componentType, false);
      if (target < 0 || target >= double(accessor.count)) fail(what + " has a sparse index out of range");
      for (int c = 0; c < components; ++c)
        values[size_t(target) * size_t(components) + size_t(c)] =
            readComponent(substitutes + sparse.values.byteOffset + k * elementSize + size_t(c * componentSize),
                          accessor.componentType, accessor.normalized);
    }
  }

  const unsigned char* viewData(int index, const std::string& what) const
  {
    if (index < 0 || size_t(index) >= model_.bufferViews.size())
      fail(what + " refers to buffer view " + std::to_string(index) + ", which does not exist");
    const tinygltf::BufferView& view = model_.bufferViews[size_t(index)];
    if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
      fail("buffer view " + std::to_string(index) + " refers to a missing buffer");
    const auto& data = model_.buffers[size_t(view.buffer)].data;
    if (view.byteOffset + view.byteLength > data.size())
      fail("buffer view " + std::to_string(index) + " reaches past the end of its buffer");
    return data.data() + view.byteOffset;
  }

  const tinygltf::Model& model_;
  std::string prefix_;
  TriangleMesh mesh_;
};

}  // namespace

TriangleMesh readGltf(const std::filesystem::path& path, MeshFormat format)
{
  const std::string prefix = "cannot read " + path.string() + ": ";
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skipImage, nullptr);
  tinygltf::Model model;
  std::string error, warning;
  const bool ok = format == MeshFormat::Glb ? loader.LoadBinaryFromFile(&model, &error, &warning, path.string())
                                            : loader.LoadASCIIFromFile(&model, &error, &warning, path.string());
  if (!warning.empty()) log::verbose(prefix + "tinygltf: " + oneLine(warning));
  if (!ok)
    throw InputError(prefix + "not a readable " + formatName(format) + " file (" +
                     oneLine(error.empty() ? "no details" : error) + ")");
  for (const auto& extension : model.extensionsRequired)
    if (unsupportedRequiredExtensions.count(extension))
      throw InputError(prefix + "it requires " + extension + ", which lbmshape cannot decode");

  SoupBuilder builder(model, prefix);
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    size_t scene =
        model.defaultScene >= 0 && size_t(model.defaultScene) < model.scenes.size() ? size_t(model.defaultScene) : 0;
    roots = model.scenes[scene].nodes;
  } else {
    // No scene: glTF leaves what to show to the application; every node that
    // is no other node's child shows everything once.
    std::vector<bool> isChild(model.nodes.size(), false);
    for (const auto& node : model.nodes)
      for (int child : node.children)
        if (child >= 0 && size_t(child) < isChild.size()) isChild[size_t(child)] = true;
    for (size_t i = 0; i < model.nodes.size(); ++i)
      if (!isChild[i]) roots.push_back(int(i));
  }
  std::vector<int> ancestors;
  for (int root : roots) builder.addNode(root, glm::dmat4(1.0), ancestors);
  return builder.take();
}

}  // namespace lbmshape
