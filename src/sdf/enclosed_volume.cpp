#include "sdf/enclosed_volume.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace lbmshape {

size_t insideCellCount(const Volume& field)
{
  return size_t(std::count_if(field.values().begin(), field.values().end(), [](float x) { return x > 0.0f; }));
}

void requireEnclosedVolume(const Volume& field, const std::filesystem::path& meshPath)
{
  if (insideCellCount(field) > 0) return;
  throw InputError("cannot use " + meshPath.string() +
                   ": it encloses no volume (its winding number is below 1/2 at every cell of the grid); an open "
                   "sheet has no inside, and a solid thinner than a voxel needs a finer --res or --voxel");
}

}  // namespace lbmshape
