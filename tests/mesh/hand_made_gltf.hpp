// glTF files put together by hand in the tests, independently of the code
// under test: the caller fills in meshes, nodes and scenes in `json`, and
// the binary arrays go into one buffer, stored in a sibling .bin file (for a
// .gltf) or in the GLB container. Also reads back the GLB files lbmshape
// writes, to look at their animation.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace lbmshape::testing::meshio {

// A unit tetrahedron with outward faces, as positions and indices.
inline const std::vector<glm::vec3> tetraCorners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
inline const std::vector<uint32_t> tetraIndices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

class HandMadeGltf {
public:
  HandMadeGltf();

  int addPositions(const std::vector<glm::vec3>& positions);  // accessor index; with min/max
  int addIndices(const std::vector<uint32_t>& indices);
  int addIndices16(const std::vector<uint16_t>& indices);
  // COLOR_0 accessors: float RGB, or normalized unsigned bytes RGBA.
  int addColours(const std::vector<glm::vec3>& colours);
  int addColours8(const std::vector<glm::u8vec4>& colours);
  // A skin's accessors: JOINTS_0 (unsigned bytes), WEIGHTS_0 (floats), and
  // inverse bind matrices (MAT4 floats, column-major).
  int addJoints(const std::vector<glm::u8vec4>& joints);
  int addWeights(const std::vector<glm::vec4>& weights);
  int addMatrices(const std::vector<glm::mat4>& matrices);
  // A mesh of one primitive; `indices` < 0 for none. Returns the mesh index.
  int addMesh(int positions, int indices, int mode = 4);

  nlohmann::json json;

  void writeGltf(const std::filesystem::path& path) const;  // and path with .bin
  void writeGlb(const std::filesystem::path& path) const;

private:
  int addView(const void* data, size_t bytes, int target);
  std::vector<unsigned char> buffer_;
};

// A GLB file split into its JSON and its binary chunk.
struct GlbContent {
  nlohmann::json json;
  std::vector<unsigned char> binary;

  // The float elements of accessor `index` (tightly packed, as lbmshape writes).
  std::vector<float> floats(int index) const;
};

GlbContent readGlb(const std::filesystem::path& path);

}  // namespace lbmshape::testing::meshio
