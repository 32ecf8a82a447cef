#include <iostream>

#include "lbmshape/core/log.hpp"
#include "mesh_commands.hpp"
#include "lbmshape/pipeline/denoise.hpp"

namespace lbmshape::cli {
namespace {

struct DenoiseArguments {
  std::string input, output;
  DenoiseOptions options;
  double voxel = 0.0;
  const CLI::Option* voxelOption = nullptr;  // given or not: every value, 0 included, is then checked
  int steps = 0;
  const CLI::Option* stepsOption = nullptr;  // not given: as many steps as the noise needs
  double radius = 0.0;
  const CLI::Option* radiusOption = nullptr;
  bool isotropic = false, anisotropic = false, preserveFeatures = false;
  std::string preview;
  std::string colour = "none";
};

void runDenoise(const CommonOptions& common, DenoiseArguments& a)
{
  // Whether --voxel was given, not its value, decides: a sentinel value
  // would let --voxel 0 (or nan) fall back to --res instead of failing.
  if (a.voxelOption->count() > 0) a.options.grid.voxel = a.voxel;
  if (a.stepsOption->count() > 0) a.options.steps = a.steps;
  if (a.radiusOption->count() > 0) a.options.radius = a.radius;
  if (a.isotropic) a.options.smoothing = Smoothing::Isotropic;
  if (a.anisotropic) a.options.smoothing = Smoothing::Anisotropic;
  if (a.preserveFeatures) a.options.smoothing = Smoothing::PreserveFeatures;
  if (!a.preview.empty()) a.options.preview = a.preview;
  a.options.colourByCurvature = a.colour == "curvature";
  checkDenoiseFileArguments(a.output, a.options);  // before the device is opened (and all run --check does)
  if (common.checkOnly) return;
  DenoiseResult result = denoiseFile(a.input, a.output, a.options, common.computeDevice());
  common.report(result.report);
  if (!common.json) {
    const auto& out = result.report["output"];
    log::info("wrote " + a.output + " (" + std::to_string(out["triangles"].get<size_t>()) + " triangles" +
              (out["closed_manifold"].get<bool>() ? ", closed" : ", open") + ") in " +
              std::to_string(int(result.report["ms"]["total"].get<double>())) + " ms");
  }
}

}  // namespace

void addDenoiseCommand(CLI::App& app, const CommonOptions& common)
{
  auto a = std::make_shared<DenoiseArguments>();
  auto* cmd =
      app.add_subcommand("denoise", "Smooth a mesh: distance field, lattice Boltzmann diffusion, marching cubes");
  cmd->add_option("input", a->input, "Mesh to smooth (.obj .ply .off .stl .gltf .glb)")->required();
  cmd->add_option("output", a->output, "Result, format by extension (.glb .gltf .obj .ply .off .stl)")->required();
  auto* res =
      cmd->add_option("--res", a->options.grid.resolution, "Grid cells along the longest side")->capture_default_str();
  a->voxelOption =
      cmd->add_option("--voxel", a->voxel, "Voxel size in the mesh's units (instead of --res)")->excludes(res);
  cmd->add_option("--margin", a->options.grid.marginVoxels, "Empty voxels around the mesh")->capture_default_str();
  auto* steps = cmd->add_option(
      "--steps", a->steps,
      "Lattice Boltzmann steps (default: as many as the noise needs, from 3 to 7, read off the field as it "
      "smooths and at least what the noise's amplitude on the input's triangles asks, twiced with 8 to 14 where "
      "the field needs 4 or more; the paper's runs: 7); with --twicing the smoothing's steps, the lattice running "
      "twice as many");
  a->stepsOption = steps;
  a->radiusOption = cmd->add_option("--radius", a->radius,
                                    "Smoothing radius in the mesh's units, instead of --steps: the steps whose "
                                    "diffusion reaches a Gaussian of this standard deviation, the same smoothing at "
                                    "any --res")
                        ->excludes(steps);
  cmd->add_option("--gamma", a->options.gamma, "Diffusion coefficient, voxels^2 per step")->capture_default_str();
  auto* preserve =
      cmd->add_flag("--preserve-features", a->preserveFeatures, "Per-cell gamma falling at sharp edges (the default)");
  auto* iso = cmd->add_flag("--isotropic", a->isotropic,
                            "One gamma everywhere: the paper's motion by mean curvature, which rounds sharp edges")
                  ->excludes(preserve);
  cmd->add_flag("--anisotropic", a->anisotropic, "Per-cell gamma = gamma + kappa, the paper's Eq. 20")
      ->excludes(preserve)
      ->excludes(iso);
  cmd->add_option(
         "--noise", a->options.noise.amplitude,
         "Add the paper's uniform noise to the distance field first, as a fraction of its largest value (0.05 = 5%)")
      ->capture_default_str();
  cmd->add_option("--seed", a->options.noise.seed, "Seed of --noise")->capture_default_str();
  cmd->add_flag_function(
      "--shrink", [a](int64_t) { a->options.keepVolume = false; },
      "Leave the result shrunk, as mean-curvature flow and the paper's scheme do, instead of "
      "shifting it to enclose the input's volume");
  auto* twicing = cmd->add_flag_function(
      "--twicing", [a](int64_t) { a->options.twicing = true; },
      "Smooth, then smooth what the smoothing took away and add it back (Tukey's twicing): keeps thin parts that "
      "smoothing erodes and removes noise as well; about twice the lattice steps (default: the default smoothing "
      "with its steps chosen by the noise is twiced, with a weight of 0.75, where the noise needs 4 steps or more)");
  cmd->add_flag_function(
         "--no-twicing", [a](int64_t) { a->options.twicing = false; },
         "Never twice the smoothing, however many steps the noise needs")
      ->excludes(twicing);
  cmd->add_option("--relax", a->options.relaxRounds,
                  "Rounds of tangential relaxation of the result's triangles: marching cubes' slivers evened out, "
                  "the surface left where it is (0: marching cubes' own triangles)")
      ->capture_default_str();
  cmd->add_flag(
      "--dense", a->options.dense,
      "Run the lattice on every cell of the grid, as the paper does, instead of the narrow band around the surface");
  cmd->add_option(
         "--color", a->colour,
         "Vertex colours of the result: none, or curvature (mean curvature, blue-grey-red; .glb, .gltf, .obj or .ply)")
      ->check(CLI::IsMember({"none", "curvature"}))
      ->capture_default_str();
  cmd->add_flag_function(
      "--compress", [a](int64_t) { a->options.compression = GltfCompression::Meshopt; },
      "Write a smaller .glb: positions and normals quantized (KHR_mesh_quantization), meshopt-encoded "
      "(EXT_meshopt_compression)");
  cmd->add_option("--preview", a->preview, "Also draw the input and the result side by side into this PNG picture");
  cmd->add_flag("--force", a->options.replaceInput, "Write the result even where the output is the input mesh");
  cmd->callback([&common, a] { runDenoise(common, *a); });
}

}  // namespace lbmshape::cli
