#include "lbmshape/mesh/gltf_skinning.hpp"

#include <algorithm>
#include <cmath>

#include "lbmshape/mesh/gltf_scene_walk.hpp"
#include "lbmshape/mesh/text_scan.hpp"

namespace lbmshape {

GltfSkins::GltfSkins(const tinygltf::Model& model, const MeshSource& source, const GltfAccessors& accessors)
    : model_(model), source_(source), accessors_(accessors), jointMatrices_(model.skins.size())
{}

const std::vector<glm::dmat4>& GltfSkins::jointMatrices(int skin)
{
  std::vector<glm::dmat4>& matrices = jointMatrices_[size_t(skin)];
  const tinygltf::Skin& s = model_.skins[size_t(skin)];
  if (!matrices.empty() || s.joints.empty()) return matrices;
  if (nodeWorld_.empty()) nodeWorld_ = nodeWorldTransforms(model_, source_);
  const std::string name = "skin " + std::to_string(skin);
  std::vector<glm::dmat4> inverseBind(s.joints.size(), glm::dmat4(1.0));  // none given: identities
  if (s.inverseBindMatrices >= 0) {
    inverseBind = accessors_.matrices(s.inverseBindMatrices, name + " inverseBindMatrices");
    if (inverseBind.size() < s.joints.size())
      source_.refuse(name + " has " + std::to_string(inverseBind.size()) + " inverse bind matrices for " +
                     std::to_string(s.joints.size()) + " joints");
  }
  for (size_t j = 0; j < s.joints.size(); ++j) {
    const int joint = s.joints[j];
    if (joint < 0 || size_t(joint) >= model_.nodes.size())
      source_.refuse(name + "'s joint " + std::to_string(j) + " is node " + std::to_string(joint) +
                     ", which does not exist");
    matrices.push_back(nodeWorld_[size_t(joint)] * inverseBind[j]);
  }
  return matrices;
}

std::vector<uint8_t> GltfSkins::pose(const tinygltf::Primitive& primitive, const std::string& name, int skin,
                                     std::vector<glm::dvec3>& positions)
{
  const std::vector<glm::dmat4>& joints = jointMatrices(skin);
  std::vector<glm::dmat4> blend(positions.size(), glm::dmat4(0.0));
  std::vector<double> total(positions.size(), 0.0);
  for (int set = 0;; ++set) {
    const auto jointsAt = primitive.attributes.find("JOINTS_" + std::to_string(set));
    const auto weightsAt = primitive.attributes.find("WEIGHTS_" + std::to_string(set));
    if (jointsAt == primitive.attributes.end() || weightsAt == primitive.attributes.end()) break;
    const std::string jointsName = name + " JOINTS_" + std::to_string(set),
                      weightsName = name + " WEIGHTS_" + std::to_string(set);
    const std::vector<glm::dvec4> indices = accessors_.quadruples(jointsAt->second, jointsName);
    const std::vector<glm::dvec4> weights = accessors_.quadruples(weightsAt->second, weightsName);
    if (indices.size() != positions.size() || weights.size() != positions.size())
      source_.refuse(name + " has " + std::to_string(indices.size()) + " joints and " + std::to_string(weights.size()) +
                     " weights (set " + std::to_string(set) + ") for " + std::to_string(positions.size()) +
                     " positions");
    for (size_t v = 0; v < positions.size(); ++v)
      for (int k = 0; k < 4; ++k) {
        const double w = weights[v][k];
        if (w == 0.0) continue;
        if (!(std::isfinite(w) && w > 0.0)) source_.refuse(weightsName + " holds a weight that is not positive");
        const double j = indices[v][k];
        // Whole numbers only (glTF: unsigned bytes or shorts); a float or
        // normalized accessor's 0.9 is no joint, and NaN none either.
        if (!(j >= 0.0 && j == std::floor(j)))
          source_.refuse(jointsName + " holds " + text::printable(std::to_string(j)) +
                         ", which is not a joint's number");
        if (j >= double(joints.size()))
          source_.refuse(jointsName + " refers to joint " + std::to_string(uint64_t(std::min(j, 1e18))) +
                         ", but skin " + std::to_string(skin) + " has " + std::to_string(joints.size()));
        blend[v] += w * joints[size_t(j)];
        total[v] += w;
      }
  }
  std::vector<uint8_t> mirrors(positions.size(), 0);
  for (size_t v = 0; v < positions.size(); ++v)
    if (total[v] > 0.0) {
      positions[v] = glm::dvec3((blend[v] / total[v]) * glm::dvec4(positions[v], 1.0));
      mirrors[v] = glm::determinant(glm::dmat3(blend[v])) < 0.0;
    }
  return mirrors;
}

}  // namespace lbmshape
