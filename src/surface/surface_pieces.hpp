// Marching cubes in two halves: the pieces of the surface (its cut grid
// edges and cut cubes), which the device lists beside the lattice so that a
// morph's frame reads back those instead of its field
// (shaders/band_surface.comp), and the mesh made from them on the host.
// listSurfacePieces() is the CPU reference of the device's pass, and
// assembleSurface(listSurfacePieces(field)) is extractSurface(field) of
// band_marching_cubes.hpp: the same vertices and triangles in the same
// order, so the closed-manifold guarantee holds for both (and a morph's
// frame figures, which sample the mesh, come out the same).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/band/band_field.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/sdf/grid_frame.hpp"

namespace lbmshape {

// A grid edge the surface cuts: key = 3 * grid index of its lower end + axis.
struct SurfaceCrossing {
  uint64_t key = 0;
  float lower = 0.0f, upper = 0.0f;  // X at its two ends
  glm::vec3 normal{0.0f};            // the unit normal at its vertex (edge_vertex::normal)

  bool operator<(const SurfaceCrossing& o) const { return key < o.key; }
};

// A cube the surface cuts: the grid index of its lower corner, its case
// (bit c set when corner c is above the isovalue, cube_cases.hpp), and its
// place in the band (slot * brickCells + cell in brick), the order in which
// extractSurface() on the band makes its triangles.
struct SurfaceCube {
  uint64_t index = 0;
  uint32_t cubeCase = 0;
  uint32_t order = 0;

  bool operator<(const SurfaceCube& o) const { return order < o.order; }
};

// What a frame asks of the field with its surface.
struct SurfaceRequest {
  float isovalue = 0.0f;
  // At least 0: also the largest |X - base| over the cells with |base| <=
  // nearBand (a morph's distance to its target, base being X_target).
  float nearBand = -1.0f;
  // Cells of the grid whose values to read as well (a morph's frame
  // report samples the frame's field near the target's surface).
  std::vector<glm::ivec3> probes{};
};

struct SurfacePieces {
  Extent3 extent;
  float isovalue = 0.0f;
  std::vector<SurfaceCrossing> crossings;  // sorted by key, each edge once (tidy())
  std::vector<SurfaceCube> cubes;          // in their order (tidy())
  // SurfaceRequest::nearBand's, where one was asked for.
  std::optional<double> errorNearBase;
  std::vector<float> probeValues;  // X at SurfaceRequest::probes, in order

  // Sorts both lists and keeps one crossing per edge: the device lists them
  // in the order its threads find them, an edge of two bricks twice.
  void tidy();
};

// Every cut edge and cut cube of the cubes whose lower corner lies in a
// stored brick and whose upper corner in the grid (those extractSurface()
// triangulates), tidied, with what `request` asks (the error near `base`
// when it is given and request.nearBand >= 0). Throws NumericalError when a
// stored value is NaN or infinite, std::invalid_argument when `base` lies
// on other bricks or a probe beyond the grid.
SurfacePieces listSurfacePieces(const BandField& field, const SurfaceRequest& request = {},
                                const BandField* base = nullptr);

// The mesh of tidied pieces, as extractSurface(field, frame, isovalue) of the
// field they were listed from. Throws std::invalid_argument when the frame's
// extent differs from theirs, NumericalError when a cube's cut edge is
// missing from the crossings.
TriangleMesh assembleSurface(const SurfacePieces& pieces, const GridFrame& frame);

}  // namespace lbmshape
