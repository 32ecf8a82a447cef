#include "lbmshape/mesh/gltf_scene_walk.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace lbmshape {
namespace {

constexpr int noParent = -1;

std::string nodeName(size_t index) { return "node " + std::to_string(index); }

// The node's transform. Its properties' types and lengths are checked
// (gltf_json_element.hpp); what is left is what the numbers mean.
glm::dmat4 localTransform(const tinygltf::Node& node, size_t index, const MeshSource& source)
{
  if (node.matrix.size() == 16) {
    const glm::dmat4 m = glm::make_mat4(node.matrix.data());  // column-major, as glTF stores it
    // glTF: a matrix decomposable into translation, rotation and scale; a
    // projective one would put a divide in every position.
    if (glm::row(m, 3) != glm::dvec4(0, 0, 0, 1))
      source.refuse(nodeName(index) + "'s matrix is not affine (its last row is not 0 0 0 1)");
    return m;
  }
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3)
    m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  if (node.rotation.size() == 4) {  // glTF: (x, y, z, w); glm's constructor: (w, x, y, z)
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    // A unit quaternion; one a little off is normalized, as renderers do,
    // but 0 0 0 0 is no rotation at all.
    if (!(glm::length(q) > 1e-6)) source.refuse(nodeName(index) + "'s rotation is not a unit quaternion");
    m = m * glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3)
    m = m * glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

// Each node's parent, checking that no node has two and none is its own ancestor.
std::vector<int> parentsOf(const tinygltf::Model& model, const MeshSource& source)
{
  const size_t n = model.nodes.size();
  std::vector<int> parent(n, noParent);
  for (size_t i = 0; i < n; ++i)
    for (int child : model.nodes[i].children) {
      if (child < 0 || size_t(child) >= n)
        source.refuse(nodeName(i) + " has child " + std::to_string(child) + ", which does not exist");
      if (parent[size_t(child)] == int(i))
        source.refuse(nodeName(i) + " lists " + nodeName(size_t(child)) +
                      " as its child twice (glTF nodes form trees)");
      if (parent[size_t(child)] != noParent)
        source.refuse(nodeName(size_t(child)) + " is a child of both " + nodeName(size_t(parent[size_t(child)])) +
                      " and " + nodeName(i) + " (glTF nodes form trees)");
      parent[size_t(child)] = int(i);
    }
  // With one parent each, following parents from any node either reaches a
  // root or goes round a cycle; each node is followed once.
  enum : uint8_t { unseen, onPath, done };
  std::vector<uint8_t> state(n, unseen);
  std::vector<size_t> path;
  for (size_t start = 0; start < n; ++start) {
    path.clear();
    for (size_t node = start;;) {
      if (state[node] == onPath) source.refuse(nodeName(node) + " is its own ancestor");
      if (state[node] == done) break;  // joins a chain already followed
      state[node] = onPath;
      path.push_back(node);
      if (parent[node] == noParent) break;
      node = size_t(parent[node]);
    }
    for (size_t p : path) state[p] = done;
  }
  return parent;
}

}  // namespace

std::vector<GltfInstance> meshInstances(const tinygltf::Model& model, const MeshSource& source)
{
  const std::vector<int> parent = parentsOf(model, source);
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    // The default scene is checked to exist (gltf_json_check.hpp); without one, scene 0.
    const size_t scene = model.defaultScene >= 0 ? size_t(model.defaultScene) : 0;
    if (scene >= model.scenes.size()) source.refuse("its default scene " + std::to_string(scene) + " does not exist");
    for (int root : model.scenes[scene].nodes) {
      if (root < 0 || size_t(root) >= model.nodes.size())
        source.refuse("scene " + std::to_string(scene) + " refers to node " + std::to_string(root) +
                      ", which does not exist");
      if (parent[size_t(root)] != noParent)
        source.refuse("scene " + std::to_string(scene) + " lists " + nodeName(size_t(root)) + ", which is a child of " +
                      nodeName(size_t(parent[size_t(root)])) + " (a scene lists root nodes)");
      roots.push_back(root);
    }
  } else {
    // No scene: glTF leaves what to show to the application; every node that
    // is no other node's child shows everything once.
    for (size_t i = 0; i < model.nodes.size(); ++i)
      if (parent[i] == noParent) roots.push_back(int(i));
  }

  std::vector<GltfInstance> instances;
  std::vector<bool> visited(model.nodes.size(), false);
  std::vector<std::pair<int, glm::dmat4>> pending;  // nodes to visit, with their parent's world transform
  for (auto root = roots.rbegin(); root != roots.rend(); ++root) pending.emplace_back(*root, glm::dmat4(1.0));
  while (!pending.empty()) {
    const auto [index, parentWorld] = pending.back();
    pending.pop_back();
    if (visited[size_t(index)]) continue;  // a root listed twice
    visited[size_t(index)] = true;
    const tinygltf::Node& node = model.nodes[size_t(index)];
    const glm::dmat4 world = parentWorld * localTransform(node, size_t(index), source);
    // Scaled to nothing (an animation's hidden frames, as lbmshape's own
    // morph.glb keeps all but the first): not shown, with all below it.
    // Read, they were each frame's triangles collapsed to a point, dropped
    // with a warning of thousands of degenerate triangles.
    if (glm::dmat3(world) == glm::dmat3(0.0)) continue;
    if (node.mesh >= 0) {
      if (size_t(node.mesh) >= model.meshes.size())
        source.refuse(nodeName(size_t(index)) + " refers to mesh " + std::to_string(node.mesh) +
                      ", which does not exist");
      const tinygltf::Mesh& mesh = model.meshes[size_t(node.mesh)];
      if (node.skin >= 0 && size_t(node.skin) >= model.skins.size())
        source.refuse(nodeName(size_t(index)) + " refers to skin " + std::to_string(node.skin) +
                      ", which does not exist");
      instances.push_back({node.mesh, world, node.weights.empty() ? &mesh.weights : &node.weights, node.skin});
    }
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
      pending.emplace_back(*child, world);
  }
  return instances;
}

std::vector<glm::dmat4> nodeWorldTransforms(const tinygltf::Model& model, const MeshSource& source)
{
  const std::vector<int> parent = parentsOf(model, source);  // trees: each chain ends at a root
  const size_t n = model.nodes.size();
  std::vector<glm::dmat4> world(n);
  std::vector<bool> known(n, false);
  std::vector<size_t> chain;
  for (size_t start = 0; start < n; ++start) {
    chain.clear();
    for (size_t node = start; !known[node];) {
      chain.push_back(node);
      if (parent[node] == noParent) break;
      node = size_t(parent[node]);
    }
    for (auto node = chain.rbegin(); node != chain.rend(); ++node) {
      const glm::dmat4 local = localTransform(model.nodes[*node], *node, source);
      world[*node] = parent[*node] == noParent ? local : world[size_t(parent[*node])] * local;
      known[*node] = true;
    }
  }
  return world;
}

}  // namespace lbmshape
