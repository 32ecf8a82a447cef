#include "lbmshape/sdf/enclosed_volume.hpp"

#include <algorithm>
#include <cmath>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"

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
                   "sheet has no inside (nor has one facing inward: its triangles must wind counter-clockwise seen "
                   "from outside), and a solid thinner than a voxel needs a finer " +
                   nameOf(Parameter::Resolution) +
                   (audienceCanSet(Parameter::Voxel) ? " or " + nameOf(Parameter::Voxel) : std::string()));
}
}  // namespace

void requireEnclosedVolume(const Volume& field, const std::filesystem::path& meshPath)
{
  if (insideCellCount(field) == 0) enclosesNothing(meshPath);
}

namespace {
// Whether a brick beyond the band lies inside.
bool insideBeyondTheBand(const BandField& field)
{
  const BrickSet& bricks = field.bricks();
  const Extent3& grid = bricks.bricks();
  for (size_t b = 0; b < field.farSides().size(); ++b)
    if (field.farSides()[b] > 0 &&
        bricks.slot(int(b % grid.nx), int(b / grid.nx % grid.ny), int(b / grid.nx / grid.ny)) == noBrick)
      return true;
  return false;
}
}  // namespace

void requireEnclosedVolume(const BandField& field, const std::filesystem::path& meshPath)
{
  const bool storedInside = std::any_of(field.values().begin(), field.values().end(), [](float x) { return x > 0.0f; });
  if (!storedInside && !insideBeyondTheBand(field)) enclosesNothing(meshPath);
}

double deepestInside(const Volume& field)
{
  const auto& v = field.values();
  return v.empty() ? 0.0 : double(*std::max_element(v.begin(), v.end()));
}

double deepestInside(const BandField& field)
{
  if (insideBeyondTheBand(field)) return std::abs(double(field.farValue()));
  const auto& v = field.values();
  return v.empty() ? -std::abs(double(field.farValue())) : double(*std::max_element(v.begin(), v.end()));
}

}  // namespace lbmshape
