#include <cmath>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/number_text.hpp"
#include "lbmshape/mesh/mesh_geometry.hpp"
#include "lbmshape/mesh/mesh_noise.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "mesh_commands.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "lbmshape/sdf/grid_frame.hpp"

namespace lbmshape::cli {
namespace {

struct NoiseArguments {
  std::string input, output;
  double sigma = 0.5;
  std::optional<int> resolution;  // set: sigma is in voxels of denoise's grid at this --res
  uint32_t seed = 1;
  bool force = false;
};

void runNoise(const CommonOptions& common, const NoiseArguments& args)
{
  // inf would pass a sign check and only fail at the writer, as an output error.
  if (!(args.sigma >= 0.0) || !std::isfinite(args.sigma))
    throw UsageError("--sigma must be a finite number, zero or positive");
  if (args.resolution) {
    GridOptions grid;
    grid.resolution = *args.resolution;
    checkGridAndNoise(grid, FieldNoise{});
  }
  checkNotTheInput(args.output, args.input, args.force);
  checkMeshDestination(args.output);
  const TriangleMesh mesh = readMesh(args.input, EmptyMesh::Refused, FlatMesh::Allowed);  // a sheet too
  const double edge = meanEdgeLength(mesh);
  // The unit of --sigma: a mean edge length, or with --res a voxel of the
  // grid `denoise --res` would put around this mesh.
  const double unit =
      args.resolution ? frameWithResolution(bounds(mesh), *args.resolution, GridOptions{}.marginVoxels).voxel : edge;
  const char* unitName = args.resolution ? "voxels" : "mean edge lengths";
  // A mesh whose edges all have zero length has no normals to move along.
  writeMesh(addNormalNoise(mesh, edge > 0.0 ? args.sigma * unit / edge : 0.0, args.seed), args.output);
  common.report({{"command", "noise"},
                 {"input", args.input},
                 {"output", args.output},
                 {"sigma", args.sigma},
                 {"sigma_unit", args.resolution ? "voxel" : "mean_edge_length"},
                 {"sigma_absolute", args.sigma * unit},
                 {"mean_edge_length", edge},
                 {"seed", args.seed}});
  if (!common.json)
    log::info("wrote " + args.output + " (noise sigma " + numberText(args.sigma * unit) + " = " +
              numberText(args.sigma) + " " + unitName + ")");
}

}  // namespace

void addNoiseCommand(CLI::App& app, const CommonOptions& common)
{
  auto args = std::make_shared<NoiseArguments>();
  auto* cmd = app.add_subcommand("noise", "Write a copy of a mesh with Gaussian vertex noise along the normals");
  cmd->add_option("input", args->input, "Mesh")->required();
  cmd->add_option("output", args->output, "Noisy copy, format by extension")->required();
  cmd->add_option("--sigma", args->sigma, "Standard deviation, in mean edge lengths (with --res: in voxels)")
      ->capture_default_str();
  cmd->add_option("--res", args->resolution,
                  "Give --sigma in voxels of the grid that denoise --res N (default margin) puts around the mesh");
  cmd->add_option("--seed", args->seed, "Random seed")->capture_default_str();
  cmd->add_flag("--force", args->force, "Write the copy even where the output is the input mesh");
  cmd->callback([&common, args] { runNoise(common, *args); });
}

}  // namespace lbmshape::cli
