// Random points spread uniformly by area over a triangle mesh, from a fixed
// seed: the same mesh and seed give the same points on every machine and for
// any number of threads.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {

struct SurfaceSample {
  glm::dvec3 point;
  uint32_t triangle;
};

// `count` points, sorted by triangle (so neighbours in the list are usually
// near each other in space). Triangles without area get none. Throws
// InputError when the mesh has no area at all.
std::vector<SurfaceSample> sampleSurface(const TriangleMesh& mesh, size_t count, uint64_t seed);

// Unit normal of each triangle, counter-clockwise; zero for a triangle without area.
std::vector<glm::dvec3> faceNormals(const TriangleMesh& mesh);

}  // namespace lbmshape
