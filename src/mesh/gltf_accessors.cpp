#include "lbmshape/mesh/gltf_accessors.hpp"

#include <algorithm>
#include <cstring>

#include "lbmshape/core/checked_arithmetic.hpp"

namespace lbmshape {
namespace {

double component(const unsigned char* p, int componentType, bool normalized)
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

uint64_t componentSize(int componentType)
{
  const int size = tinygltf::GetComponentSizeInBytes(uint32_t(componentType));
  return size > 0 ? uint64_t(size) : 0;
}

}  // namespace

GltfAccessors::GltfAccessors(const tinygltf::Model& model, const MeshSource& source, uint64_t elementLimit)
    : model_(model), source_(source), elementLimit_(elementLimit)
{}

const tinygltf::Accessor& GltfAccessors::accessor(int index, int type, const std::string& what) const
{
  if (index < 0 || size_t(index) >= model_.accessors.size())
    fail(what + " refers to accessor " + std::to_string(index) + ", which does not exist");
  const tinygltf::Accessor& a = model_.accessors[size_t(index)];
  if (a.type != type || componentSize(a.componentType) == 0)
    fail(what + " (accessor " + std::to_string(index) + ") has the wrong type");
  return a;
}

GltfAccessors::Span GltfAccessors::span(int bufferView, uint64_t byteOffset, uint64_t count, uint64_t elementSize,
                                        bool strided, const std::string& what) const
{
  if (bufferView < 0 || size_t(bufferView) >= model_.bufferViews.size())
    fail(what + " refers to buffer view " + std::to_string(bufferView) + ", which does not exist");
  const tinygltf::BufferView& view = model_.bufferViews[size_t(bufferView)];
  const std::string name = "buffer view " + std::to_string(bufferView);
  if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size()) fail(name + " refers to a missing buffer");
  const auto viewEnd = checkedAdd(view.byteOffset, view.byteLength);
  if (!viewEnd || *viewEnd > model_.buffers[size_t(view.buffer)].data.size())
    fail(name + " reaches past the end of its buffer");
  const uint64_t stride = strided && view.byteStride ? view.byteStride : elementSize;
  if (stride < elementSize)
    fail(name + "'s byteStride " + std::to_string(stride) + " is less than an element of " + what);
  if (byteOffset > view.byteLength) fail(what + " begins past the end of " + name);
  if (count > 0) {
    // byteOffset + stride * (count - 1) + elementSize, without wrapping.
    const auto last = checkedMultiply(stride, count - 1);
    const auto start = last ? checkedAdd(byteOffset, *last) : std::nullopt;
    const auto end = start ? checkedAdd(*start, elementSize) : std::nullopt;
    if (!end || *end > view.byteLength) fail(what + " reads past the end of " + name);
  }
  return {model_.buffers[size_t(view.buffer)].data.data() + view.byteOffset + byteOffset, stride};
}

uint64_t GltfAccessors::count(int index, int type, const std::string& what) const
{
  const tinygltf::Accessor& a = accessor(index, type, what);
  const uint64_t elementSize =
      componentSize(a.componentType) * uint64_t(tinygltf::GetNumComponentsInType(uint32_t(a.type)));
  if (a.bufferView >= 0)
    span(a.bufferView, a.byteOffset, a.count, elementSize, true, what);
  else if (a.count > elementLimit_)
    fail(what + " (accessor " + std::to_string(index) + ") has " + std::to_string(a.count) +
         " elements but no data, more than a file of this size can describe");
  return a.count;
}

template <typename Store>
void GltfAccessors::read(const tinygltf::Accessor& a, int components, const std::string& what, Store store) const
{
  const uint64_t size = componentSize(a.componentType);
  const uint64_t elementSize = size * uint64_t(components);
  if (a.bufferView >= 0) {
    const Span s = span(a.bufferView, a.byteOffset, a.count, elementSize, true, what);
    for (uint64_t i = 0; i < a.count; ++i)
      for (int c = 0; c < components; ++c)
        store(i, c, component(s.data + i * s.stride + uint64_t(c) * size, a.componentType, a.normalized));
  }
  if (!a.sparse.isSparse) return;
  const auto& sparse = a.sparse;
  const uint64_t indexSize = componentSize(sparse.indices.componentType);
  if (sparse.count < 0 || uint64_t(sparse.count) > a.count)
    fail(what + " has " + std::to_string(sparse.count) + " sparse elements, not between 0 and its count");
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) fail(what + " has a negative sparse byteOffset");
  if (indexSize == 0 || sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
      sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_DOUBLE)
    fail(what + " has sparse indices of a type that is not an unsigned integer");
  const uint64_t n = uint64_t(sparse.count);
  const Span indices = span(sparse.indices.bufferView, uint64_t(sparse.indices.byteOffset), n, indexSize, false, what);
  const Span values = span(sparse.values.bufferView, uint64_t(sparse.values.byteOffset), n, elementSize, false, what);
  for (uint64_t k = 0; k < n; ++k) {
    const double target = component(indices.data + k * indexSize, sparse.indices.componentType, false);
    if (!(target >= 0 && target < double(a.count))) fail(what + " has a sparse index out of range");
    for (int c = 0; c < components; ++c)
      store(uint64_t(target), c,
            component(values.data + k * elementSize + uint64_t(c) * size, a.componentType, a.normalized));
  }
}

std::vector<glm::dvec3> GltfAccessors::vectors(int index, const std::string& what) const
{
  const tinygltf::Accessor& a = accessor(index, TINYGLTF_TYPE_VEC3, what);
  std::vector<glm::dvec3> out(count(index, TINYGLTF_TYPE_VEC3, what), glm::dvec3(0.0));
  read(a, 3, what, [&](uint64_t i, int c, double value) { out[i][c] = value; });
  return out;
}

std::vector<glm::vec3> GltfAccessors::colours(int index, const std::string& what) const
{
  const bool withAlpha = index >= 0 && size_t(index) < model_.accessors.size() &&
                         model_.accessors[size_t(index)].type == TINYGLTF_TYPE_VEC4;
  const int type = withAlpha ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3;
  const tinygltf::Accessor& a = accessor(index, type, what);
  std::vector<glm::vec3> out(count(index, type, what), glm::vec3(0.0f));  // no buffer view: zeros, as glTF says
  read(a, withAlpha ? 4 : 3, what, [&](uint64_t i, int c, double value) {
    if (c < 3) out[i][c] = float(std::isfinite(value) ? std::clamp(value, 0.0, 1.0) : 0.0);
  });
  return out;
}

std::vector<glm::dvec4> GltfAccessors::quadruples(int index, const std::string& what) const
{
  const tinygltf::Accessor& a = accessor(index, TINYGLTF_TYPE_VEC4, what);
  std::vector<glm::dvec4> out(count(index, TINYGLTF_TYPE_VEC4, what), glm::dvec4(0.0));
  read(a, 4, what, [&](uint64_t i, int c, double value) { out[i][c] = value; });
  return out;
}

std::vector<glm::dmat4> GltfAccessors::matrices(int index, const std::string& what) const
{
  const tinygltf::Accessor& a = accessor(index, TINYGLTF_TYPE_MAT4, what);
  std::vector<glm::dmat4> out(count(index, TINYGLTF_TYPE_MAT4, what), glm::dmat4(0.0));
  read(a, 16, what, [&](uint64_t i, int c, double value) { out[i][c / 4][c % 4] = value; });
  return out;
}

std::vector<uint32_t> GltfAccessors::indices(int index, uint64_t below, const std::string& what) const
{
  const tinygltf::Accessor& a = accessor(index, TINYGLTF_TYPE_SCALAR, what);
  if (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || a.componentType == TINYGLTF_COMPONENT_TYPE_DOUBLE)
    fail(what + " (accessor " + std::to_string(index) + ") holds floating-point numbers, not indices");
  std::vector<uint32_t> out(count(index, TINYGLTF_TYPE_SCALAR, what), 0);
  read(a, 1, what, [&](uint64_t i, int, double value) {
    if (!(value >= 0 && value < double(below)))
      fail(what + " has index " + std::to_string(int64_t(value)) + " but only " + std::to_string(below) + " vertices");
    out[i] = uint32_t(value);
  });
  return out;
}

}  // namespace lbmshape
