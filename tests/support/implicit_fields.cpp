#include "support/implicit_fields.hpp"

#include <cmath>

namespace lbmshape::testing {

GridFrame cubicFrame(Extent3 extent, double voxel, glm::dvec3 origin)
{
  GridFrame frame;
  frame.origin = origin;
  frame.voxel = voxel;
  frame.extent = extent;
  return frame;
}

Volume sampleImplicit(const GridFrame& frame, const ImplicitFunction& f)
{
  const Extent3 e = frame.extent;
  Volume v(e);
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y)
      for (int x = 0; x < e.nx; ++x) v.at(x, y, z) = float(f(frame.cellCentre(x, y, z)) / frame.voxel);
  return v;
}

double sphereSdf(const glm::dvec3& p, const glm::dvec3& centre, double radius)
{
  return radius - glm::length(p - centre);
}

double torusSdf(const glm::dvec3& p, const glm::dvec3& centre, double R, double r)
{
  const glm::dvec3 d = p - centre;
  const double ring = std::sqrt(d.x * d.x + d.y * d.y) - R;
  return r - std::sqrt(ring * ring + d.z * d.z);
}

}  // namespace lbmshape::testing
