#include "lbmshape/render/curvature_colours.hpp"

#include "lbmshape/render/colour_map.hpp"
#include "lbmshape/render/surface_values.hpp"

namespace lbmshape::render {

double curvatureScale(const TriangleMesh& mesh) { return curvatureScale(vertexMeanCurvature(mesh)); }

double curvatureScale(const std::vector<double>& meanCurvatures)
{
  const double scale = quantile(meanCurvatures, 0.95, true);
  return scale > 0.0 ? scale : 1.0;
}

std::vector<glm::vec3> curvatureColours(const TriangleMesh& mesh, double scale)
{
  const std::vector<double> curvature = vertexMeanCurvature(mesh);
  std::vector<glm::vec3> colours(curvature.size());
  for (size_t v = 0; v < curvature.size(); ++v) colours[v] = divergingColour(curvature[v] / scale);
  return colours;
}

}  // namespace lbmshape::render
