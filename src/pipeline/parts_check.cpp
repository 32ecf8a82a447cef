#include "lbmshape/pipeline/parts_check.hpp"

#include <iomanip>
#include <sstream>

#include "lbmshape/core/log.hpp"
#include "lbmshape/core/parameter_names.hpp"

namespace lbmshape {

void warnIfThePartsChanged(const MeshTopology& wanted, const std::string& wantedName, const MeshTopology& made,
                           const std::string& madeName, double voxel)
{
  if (!wanted.closedManifold || !made.closedManifold || !wanted.genus || !made.genus) return;
  if (wanted.components == made.components && *wanted.genus == *made.genus) return;
  const auto parts = [](size_t n) { return std::to_string(n) + (n == 1 ? " part" : " parts"); };
  std::ostringstream m;
  m << madeName << " has " << parts(made.components) << " of genus " << *made.genus << " where " << wantedName
    << " has " << parts(wanted.components) << " of genus " << *wanted.genus
    << ": parts or gaps thinner than about two voxels (voxel " << std::setprecision(3) << voxel
    << ") were cut or closed on this grid; a finer " << nameOf(Parameter::Resolution) << " keeps them";
  log::warning(m.str());
}

}  // namespace lbmshape
