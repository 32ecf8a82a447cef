// Vertices coloured by mean curvature, as `--color curvature` writes them
// into denoise's output and morph's frames (COLOR_0) and `render` draws
// them: the diverging map of colour_map.hpp over ±scale, blue concave, grey
// flat, red convex.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"

namespace lbmshape::render {

// The 95th percentile of |H| over the mesh's vertices (1 / its units): a
// scale that noise or a sharp edge does not wash out. 1 for a mesh without
// curvature.
double curvatureScale(const TriangleMesh& mesh);
// The same over mean curvatures already computed (of several meshes).
double curvatureScale(const std::vector<double>& meanCurvatures);

// The mesh's vertices' colours (sRGB, as TriangleMesh keeps them) for H on
// the diverging map over [-scale, scale].
std::vector<glm::vec3> curvatureColours(const TriangleMesh& mesh, double scale);

}  // namespace lbmshape::render
