// Analytic shapes sampled as fields for marching cubes: signed distances in
// voxels, positive inside, so extracted meshes can be checked against exact
// areas, volumes and normals.
#pragma once

#include <functional>

#include <glm/glm.hpp>

#include "lbmshape/core/volume.hpp"
#include "lbmshape/sdf/grid_frame.hpp"

namespace lbmshape::testing {

using ImplicitFunction = std::function<double(const glm::dvec3& world)>;

// A frame with `extent` cells, cell (0, 0, 0) at `origin` and cubic voxels.
GridFrame cubicFrame(Extent3 extent, double voxel = 1.0, glm::dvec3 origin = glm::dvec3(0.0));

// f at every cell centre of `frame`, divided by the voxel (so in voxels).
Volume sampleImplicit(const GridFrame& frame, const ImplicitFunction& f);

// Signed distances (positive inside) in world units.
double sphereSdf(const glm::dvec3& p, const glm::dvec3& centre, double radius);
// A torus around the z axis through `centre`: tube radius r at distance R.
double torusSdf(const glm::dvec3& p, const glm::dvec3& centre, double R, double r);

}  // namespace lbmshape::testing
