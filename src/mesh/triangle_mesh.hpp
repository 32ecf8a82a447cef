// A triangle mesh as lbmshape moves it around: positions in the input's own
// coordinates and units (double, so meshes far from the origin keep their
// precision), triangles as vertex index triples, and optional unit normals.
// It is a soup: nothing here assumes the mesh is closed or manifold.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace lbmshape {

// The library reads these vectors as tightly packed doubles and unsigned
// ints: a program built with GLM's aligned types (GLM_FORCE_DEFAULT_ALIGNED_GENTYPES
// with GLM_FORCE_INTRINSICS pads a dvec3 to 32 bytes) would hand it meshes
// it misreads. Caught where the program includes this header.
static_assert(sizeof(glm::dvec3) == 3 * sizeof(double) && sizeof(glm::uvec3) == 3 * sizeof(unsigned) &&
                  sizeof(glm::vec3) == 3 * sizeof(float),
              "lbmshape needs GLM's packed vector layout: do not define GLM_FORCE_DEFAULT_ALIGNED_GENTYPES");

// Whether a mesh without triangles may be written or read. Usually it is a
// mistake (a denoised mesh that vanished, an input with nothing to smooth);
// a morph's frame may be empty while the shape passes through nothing, and
// is written as a file with no triangles, which render draws as such.
enum class EmptyMesh { Refused, Allowed };
// Whether a mesh that encloses no volume because it is flat (all in one
// plane, a single triangle) is refused: what must be solid (an input to
// smooth or morph) refuses it, what only measures or draws a surface
// (compare, noise, render) takes it.
enum class FlatMesh { Refused, Allowed };

struct TriangleMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::uvec3> triangles;
  std::vector<glm::vec3> normals;  // per vertex; empty when not known
  // Per vertex, as shown on a screen (sRGB, 0..1): a scan's colours (glTF
  // COLOR_0, PLY red/green/blue), which the pictures show as they are.
  // Empty when the file has none; lbmshape's own results have none.
  std::vector<glm::vec3> colours;

  size_t vertexCount() const { return positions.size(); }
  size_t triangleCount() const { return triangles.size(); }
};

struct Bounds {
  glm::dvec3 min{0.0}, max{0.0};
  glm::dvec3 size() const { return max - min; }
  glm::dvec3 centre() const { return 0.5 * (min + max); }
  double diagonal() const { return glm::length(size()); }
};

// Bounds of the vertices that triangles use. Throws InputError when a
// triangle refers to a vertex the mesh lacks (a mesh from a program, not
// yet validated).
Bounds bounds(const TriangleMesh& mesh);

}  // namespace lbmshape
