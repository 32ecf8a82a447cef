#include "lbmshape/bench/denoise_stages.hpp"

#include <cstdio>

#include "lbmshape/mesh/icosphere.hpp"
#include "lbmshape/mesh/mesh_noise.hpp"
#include "lbmshape/pipeline/denoise.hpp"

namespace lbmshape {

nlohmann::json timeDenoiseStages(int resolution, bool dense, const ComputeDevice& device, double benchMlups)
{
  const TriangleMesh sphere = addNormalNoise(icosphere(6), 0.3, 1);
  DenoiseOptions options;
  options.grid.resolution = resolution;
  options.dense = dense;
  const nlohmann::json report = denoiseMesh(sphere, "the bench's noisy sphere", options, device).report;
  const nlohmann::json& ms = report["ms"];
  const double total = ms["total"].get<double>();
  const nlohmann::json& mlups = report["mlups"];
  return {
      {"mesh", "icosphere of " + std::to_string(sphere.triangles.size()) + " triangles, normal noise 0.3 edge lengths"},
      {"res", resolution},
      {"lattice", report["lattice"]},
      {"steps_run", report["steps_run"]},
      {"ms", ms},
      {"mlups", mlups},
      {"lattice_share", total > 0 ? ms.value("lbm", 0.0) / total : 0.0},
      {"mlups_over_bench", mlups.is_number() && benchMlups > 0 ? nlohmann::json(mlups.get<double>() / benchMlups)
                                                               : nlohmann::json(nullptr)}};
}

std::string describeDenoiseStages(const nlohmann::json& s)
{
  const nlohmann::json& ms = s["ms"];
  auto stage = [&](const char* name) { return ms.value(name, 0.0); };
  char line[512];
  std::snprintf(
      line, sizeof line,
      "  a whole denoise at --res %d (%s, %s): %.0f ms: sdf %.0f, setup %.0f, lbm %.0f (%d steps, %.1f MLUPS, "
      "%.2fx the timed runs'), extract %.0f; the lattice is %.0f%% of it\n",
      s["res"].get<int>(), s["lattice"].value("kind", "?").c_str(), s["mesh"].get<std::string>().c_str(),
      stage("total"), stage("sdf"), stage("setup"), stage("lbm"), s["steps_run"].get<int>(),
      s["mlups"].is_number() ? s["mlups"].get<double>() : 0.0,
      s["mlups_over_bench"].is_number() ? s["mlups_over_bench"].get<double>() : 0.0, stage("extract"),
      100.0 * s["lattice_share"].get<double>());
  return line;
}

}  // namespace lbmshape
