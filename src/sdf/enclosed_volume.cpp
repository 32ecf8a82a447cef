#include "sdf/enclosed_volume.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/parameter_names.hpp"

namespace lbmshape {

size_t insideCellCount(const Volume& field)
{
  return size_t(std::count_if(field.values().begin(), field.values().end(), [](float x) { return x > 0.0f; }));
}

namespace {
[[noreturn]] void enclosesNothing(const std::filesystem::path& meshPath)
{
  throw InputError("cannot use " + meshPath.string() +
                   ": it encloses no volume (its winding number is below 1/2 at every cell of the grid); an open "
                   "sheet has no inside, and a solid thinner than a voxel needs a finer " +
                   nameOf(Parameter::Resolution) +
                   (audienceCanSet(Parameter::Voxel) ? " or " + nameOf(Parameter::Voxel) : std::string()));
}
}  // namespace

void requireEnclosedVolume(const Volume& field, const std::filesystem::path& meshPath)
{
  if (insideCellCount(field) == 0) enclosesNothing(meshPath);
}

void requireEnclosedVolume(const BandField& field, const std::filesystem::path& meshPath)
{
  const bool storedInside = std::any_of(field.values().begin(), field.values().end(), [](float x) { return x > 0.0f; });
  const BrickSet& bricks = field.bricks();
  bool farInside = false;
  for (size_t b = 0; b < field.farSides().size() && !farInside; ++b) {
    const Extent3& grid = bricks.bricks();
    farInside = field.farSides()[b] > 0 &&
                bricks.slot(int(b % grid.nx), int(b / grid.nx % grid.ny), int(b / grid.nx / grid.ny)) == noBrick;
  }
  if (!storedInside && !farInside) enclosesNothing(meshPath);
}

}  // namespace lbmshape
