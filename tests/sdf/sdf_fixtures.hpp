// Meshes built in code for the signed distance tests (on top of
// support/test_meshes.hpp), and brute-force oracles that share no code with
// src/sdf.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>

#include <glm/glm.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape::testing::sdf {

// The mesh without `count` triangles picked at random (seeded), leaving
// holes; the removed triangles are spread over the surface.
TriangleMesh withHoles(const TriangleMesh& mesh, size_t count, uint32_t seed);
// The least distance from `centre` to the plane of any face of a sphere
// mesh: the polygon lies between this radius and the sphere's (the faces
// sag below the sphere by at most the difference).
double innerRadius(const TriangleMesh& sphere, const glm::dvec3& centre);

// A point drawn uniformly from the cube [-scale, scale]³.
glm::dvec3 randomPoint(std::mt19937& rng, double scale);

// Oracles. Exact distance to the mesh by projection onto each triangle's
// plane (barycentric test) or else its three edges, over all triangles.
double bruteForceDistance(const TriangleMesh& mesh, const glm::dvec3& p);
// Generalized winding number: sum of solid angles from the triangle's
// spherical excess (L'Huilier's theorem), signed by orientation.
double bruteForceWindingNumber(const TriangleMesh& mesh, const glm::dvec3& p);

}  // namespace lbmshape::testing::sdf
