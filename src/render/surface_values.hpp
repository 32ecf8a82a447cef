// Values on a surface's vertices that the pictures colour by.
#pragma once

#include <vector>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape {
class TriangleBvh;
}

namespace lbmshape::render {

// Discrete mean curvature at each vertex, in 1 / the mesh's units: half the
// component of the cotangent Laplacian of the positions (Meyer et al. 2003,
// mixed Voronoi areas) along the outward area-weighted normal. Positive where
// the surface is convex (a sphere of radius r: 1/r), negative where it is
// concave. 0 at vertices with no area around them. Open boundaries bias the
// vertices on them, as with any one-ring estimate.
std::vector<double> vertexMeanCurvature(const TriangleMesh& mesh);

// Distance from each vertex to the surface `reference` holds, in the mesh's
// units (the same units as the reference's).
std::vector<double> vertexDistances(const TriangleMesh& mesh, const TriangleBvh& reference);

// The value below which `fraction` of all the values lie (absolute values
// when `magnitude`): a colour scale that a few outliers do not wash out.
double quantile(std::vector<double> values, double fraction, bool magnitude);

}  // namespace lbmshape::render
