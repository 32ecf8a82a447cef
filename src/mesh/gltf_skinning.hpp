// Skinned meshes, posed as a viewer shows them without playing an
// animation: each vertex moved by its joints' world transforms (glTF 2.0,
// 3.7.3). The node that holds a skinned mesh places nothing: its own
// transform is ignored, as the specification says, and the joints alone
// put the mesh where it is drawn. Before, the skin was ignored and the
// node's transform applied: a character came out in its bind pose at the
// wrong place (the node's translation of 100 added, a raised arm down).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "lbmshape/mesh/gltf_accessors.hpp"
#include "lbmshape/mesh/mesh_source.hpp"

namespace lbmshape {

class GltfSkins {
public:
  GltfSkins(const tinygltf::Model& model, const MeshSource& source, const GltfAccessors& accessors);

  // Moves the primitive's positions by skin `skin` (an index checked by the
  // scene walk): each by the weighted sum of its joints' matrices (joint's
  // world transform times its inverse bind matrix), over every
  // JOINTS_n/WEIGHTS_n pair it has; weights are scaled to sum to 1, and a
  // vertex whose weights are all 0 stays as it is. Returns, per vertex,
  // whether its matrix mirrors (a triangle most of whose corners mirror
  // turns, as a mirroring node's faces do). Throws InputError for a joint
  // that is no whole number or past the skin's, a weight that is not
  // positive, or a count that does not match the positions.
  std::vector<uint8_t> pose(const tinygltf::Primitive& primitive, const std::string& name, int skin,
                            std::vector<glm::dvec3>& positions);

private:
  const std::vector<glm::dmat4>& jointMatrices(int skin);

  const tinygltf::Model& model_;
  const MeshSource& source_;
  const GltfAccessors& accessors_;
  std::vector<glm::dmat4> nodeWorld_;                   // every node's, made at the first skin
  std::vector<std::vector<glm::dmat4>> jointMatrices_;  // per skin, made when first needed
};

}  // namespace lbmshape
