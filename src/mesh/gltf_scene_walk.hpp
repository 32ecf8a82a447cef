// Which meshes a glTF scene shows, and where: the node trees walked without
// recursion (a file controls their depth), after checking that they are
// trees, as glTF requires. Nodes that share a child would otherwise double
// the work at every level (2^20 paths from a 1 KB file).
#pragma once

#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include "lbmshape/mesh/mesh_source.hpp"

namespace lbmshape {

struct GltfInstance {
  int mesh;          // an index into model.meshes, checked
  glm::dmat4 world;  // the node's world transform
  // The weights of the mesh's morph targets: the node's, else the mesh's
  // (glTF 2.0, 3.7.2.2); empty: none.
  const std::vector<double>* weights;
  int skin = -1;  // the node's skin (an index into model.skins, checked), or -1
};

// The meshes of the scene to show (the default scene, else scene 0, else
// every node without a parent), each with its node's world transform, in
// depth-first order; a node scaled to nothing (a hidden frame) is left out
// with everything below it. Throws InputError for an index out of range, a node
// that is its own ancestor, a node with two parents, or a scene that lists
// a node that is not a root.
std::vector<GltfInstance> meshInstances(const tinygltf::Model& model, const MeshSource& source);

// Every node's world transform, in or out of the scene (a skin's joints are
// nodes, and may lie outside the scene's trees). Throws as meshInstances().
std::vector<glm::dmat4> nodeWorldTransforms(const tinygltf::Model& model, const MeshSource& source);

}  // namespace lbmshape
