// The elements of glTF accessors, read safely: every count, offset and
// stride is checked, in arithmetic that cannot wrap, against the bytes that
// are actually there before any memory is reserved or any byte read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "lbmshape/mesh/mesh_source.hpp"

namespace lbmshape {

class GltfAccessors {
public:
  // `elementLimit` bounds accessors without a buffer view (all zeros, or
  // sparse), whose count no bytes back: no file needs more elements than it
  // has bytes.
  GltfAccessors(const tinygltf::Model& model, const MeshSource& source, uint64_t elementLimit);

  // The accessor's element count, after checking that its elements lie
  // inside its buffer view (or below the limit). `what` names it in messages.
  uint64_t count(int accessor, int type, const std::string& what) const;

  // A VEC3 accessor's elements (float, or normalized integers scaled to
  // [-1, 1] or [0, 1], as glTF defines them), sparse substitution applied.
  std::vector<glm::dvec3> vectors(int accessor, const std::string& what) const;
  // A VEC3 or VEC4 accessor's elements as RGB (alpha dropped), each in
  // [0, 1]: COLOR_0 (float, or normalized unsigned integers).
  std::vector<glm::vec3> colours(int accessor, const std::string& what) const;
  // A VEC4 accessor's elements (float, integers as they are, or normalized
  // integers scaled as glTF defines them): a skin's JOINTS_n and WEIGHTS_n.
  std::vector<glm::dvec4> quadruples(int accessor, const std::string& what) const;
  // A MAT4 accessor's elements (column-major, as glTF stores them): a skin's
  // inverse bind matrices.
  std::vector<glm::dmat4> matrices(int accessor, const std::string& what) const;
  // A SCALAR accessor's elements as indices; each must be below `below`.
  std::vector<uint32_t> indices(int accessor, uint64_t below, const std::string& what) const;

private:
  // Where the accessor's (or a sparse part's) bytes begin, checked.
  struct Span {
    const unsigned char* data = nullptr;  // null: no buffer view, all zeros
    uint64_t stride = 0;
  };

  const tinygltf::Accessor& accessor(int index, int type, const std::string& what) const;
  Span span(int bufferView, uint64_t byteOffset, uint64_t count, uint64_t elementSize, bool strided,
            const std::string& what) const;
  template <typename Store>
  void read(const tinygltf::Accessor& a, int components, const std::string& what, Store store) const;
  [[noreturn]] void fail(const std::string& what) const { source_.refuse(what); }

  const tinygltf::Model& model_;
  const MeshSource& source_;
  uint64_t elementLimit_;
};

}  // namespace lbmshape
