#include "lbmshape/mesh/vertex_welding.hpp"

#include <bit>
#include <cstdint>
#include <random>

namespace lbmshape {
namespace {

// Keyed by a seed drawn once per process: a file cannot be made of
// positions that all fall into one bucket (which would make the probing
// quadratic) without knowing it. The result does not depend on the seed.
uint64_t seed()
{
  static const uint64_t value = (uint64_t(std::random_device()()) << 32) ^ std::random_device()();
  return value;
}

uint64_t mix(uint64_t h)  // MurmurHash3's finaliser
{
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ull;
  return h ^ (h >> 33);
}

uint64_t hashOf(const glm::dvec3& p, uint64_t key)
{
  uint64_t h = key;
  for (int k = 0; k < 3; ++k) h = mix(h ^ std::bit_cast<uint64_t>(p[k] + 0.0));  // + 0.0 turns -0 into +0
  return h;
}

}  // namespace

TriangleMesh weldEqualPositions(const std::vector<glm::dvec3>& corners)
{
  // Open addressing with linear probing over a power-of-two table at most
  // half full: a hash map of this size made of nodes would cost several
  // times the memory and time.
  size_t capacity = 16;
  while (capacity < 2 * corners.size()) capacity *= 2;
  std::vector<uint32_t> slots(capacity, UINT32_MAX);  // vertex number, or empty
  const uint64_t key = seed();
  TriangleMesh mesh;
  mesh.triangles.resize(corners.size() / 3);
  for (size_t c = 0; c < corners.size() / 3 * 3; ++c) {
    const glm::dvec3 p = corners[c] + 0.0;
    size_t slot = hashOf(p, key) & (capacity - 1);
    while (slots[slot] != UINT32_MAX && mesh.positions[slots[slot]] != p) slot = (slot + 1) & (capacity - 1);
    if (slots[slot] == UINT32_MAX) {
      slots[slot] = uint32_t(mesh.positions.size());
      mesh.positions.push_back(p);
    }
    mesh.triangles[c / 3][int(c % 3)] = slots[slot];
  }
  return mesh;
}

TriangleMesh weldEqualPositions(const TriangleMesh& mesh)
{
  std::vector<glm::dvec3> corners;
  corners.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) corners.push_back(mesh.positions[t[k]]);
  TriangleMesh joined = weldEqualPositions(corners);
  const auto carry = [&](const auto& perVertex, auto& into) {
    if (perVertex.size() != mesh.positions.size()) return;
    into.resize(joined.positions.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) into[joined.triangles[t][k]] = perVertex[mesh.triangles[t][k]];
  };
  carry(mesh.normals, joined.normals);
  carry(mesh.colours, joined.colours);
  return joined;
}

}  // namespace lbmshape
