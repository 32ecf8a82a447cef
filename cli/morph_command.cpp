#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"
#include "mesh_commands.hpp"
#include "lbmshape/pipeline/morph.hpp"

namespace lbmshape::cli {
namespace {

struct MorphArguments {
  std::string source, target, folder;
  MorphOptions options;
  double voxel = 0.0;
  int stepsPerFrame = 0, steps = 0;
  // Whether each option was given at all: "--steps 0" is a value to check
  // (and refuse), not the same as no --steps.
  CLI::Option *voxelGiven = nullptr, *stepsPerFrameGiven = nullptr, *stepsGiven = nullptr;
  bool noAnimation = false;
  bool dense = false, band = false;  // --band is the default, kept for scripts that name it
  std::string preview;
  std::string colour = "none";
};

void runMorph(const CommonOptions& common, MorphArguments& a)
{
  if (a.voxelGiven->count()) a.options.grid.voxel = a.voxel;
  if (a.stepsPerFrameGiven->count()) a.options.stepsPerFrame = a.stepsPerFrame;
  if (a.stepsGiven->count()) a.options.steps = a.steps;
  a.options.animation = !a.noAnimation;
  a.options.band = !a.dense;
  // The paper's noise is added on the grid: the band cannot run it.
  if (a.band && a.options.noise.amplitude > 0.0)
    throw UsageError(
        "--band and --noise: the noise is added to the whole grid, which runs on every cell (--noise "
        "implies --dense); leave out --band");
  if (!a.preview.empty()) a.options.preview = a.preview;
  a.options.colourByCurvature = a.colour == "curvature";
  a.options.frameFigures = common.json;  // only the JSON report shows them
  checkMorphOptions(a.options);          // before the device is opened
  if (common.checkOnly) return;
  nlohmann::json report = morphFiles(a.source, a.target, a.folder, a.options, common.computeDevice());
  common.report(report);
  if (!common.json)
    log::info("wrote " + std::to_string(a.options.frames) + " frames to " + a.folder +
              (a.options.animation ? " and the animation " + report["animation"].get<std::string>() : "") +
              "; mean distance of the last frame to the target " +
              std::to_string(report["final"]["mean_distance_to_target_voxels"].get<double>()) + " voxels");
}

}  // namespace

void addMorphCommand(CLI::App& app, const CommonOptions& common)
{
  auto a = std::make_shared<MorphArguments>();
  auto* cmd = app.add_subcommand("morph", "Morph one mesh into another; write the frames and an animated morph.glb");
  cmd->add_option("source", a->source, "Mesh to start from")->required();
  cmd->add_option("target", a->target, "Mesh to end at")->required();
  cmd->add_option("output", a->folder, "Folder for frame_0000.glb ... and morph.glb")->required();
  auto* res =
      cmd->add_option("--res", a->options.grid.resolution, "Grid cells along the longest side")->capture_default_str();
  a->voxelGiven =
      cmd->add_option("--voxel", a->voxel, "Voxel size in the source's units (instead of --res)")->excludes(res);
  cmd->add_option("--margin", a->options.grid.marginVoxels, "Empty voxels around both meshes")->capture_default_str();
  cmd->add_option("--align", a->options.align, "Place the target: none, center (on the source), fit (center and scale)")
      ->transform(
          namedChoices<Alignment>({{"none", Alignment::None}, {"center", Alignment::Center}, {"fit", Alignment::Fit}}))
      ->default_str("fit");
  cmd->add_option("--cs", a->options.cs, "Morphing speed Cs of the force Cs (X_target - X)")->capture_default_str();
  cmd->add_option("--gamma", a->options.gamma, "Diffusion coefficient, voxels^2 per step")->capture_default_str();
  cmd->add_option("--frames", a->options.frames, "Frames, the source and the result included")->capture_default_str();
  a->stepsPerFrameGiven = cmd->add_option("--steps-per-frame", a->stepsPerFrame,
                                          "Lattice steps between frames, constant gamma and Cs (the paper's scheme); "
                                          "by default the morph runs until it arrives at the target");
  a->stepsGiven =
      cmd->add_option("--steps", a->steps, "Lattice steps in all, spread over the frames, constant gamma and Cs")
          ->excludes(a->stepsPerFrameGiven);
  cmd->add_option("--format", a->options.format, "Frame files: glb, gltf, obj, ply, off or stl")->capture_default_str();
  CLI::Option* fps = cmd->add_option("--fps", a->options.fps, "Frames per second of morph.glb")->capture_default_str();
  cmd->add_flag("--no-animation", a->noAnimation, "Do not write morph.glb")->excludes(fps);
  cmd->add_option("--color", a->colour,
                  "Vertex colours of the frames: none, or curvature (mean curvature on the target's scale)")
      ->check(CLI::IsMember({"none", "curvature"}))
      ->capture_default_str();
  cmd->add_flag_function(
      "--compress", [a](int64_t) { a->options.compression = GltfCompression::Meshopt; },
      "Smaller .glb frames and morph.glb: quantized (KHR_mesh_quantization), meshopt-encoded "
      "(EXT_meshopt_compression)");
  cmd->add_option("--preview", a->preview,
                  "Also draw a contact sheet into this PNG picture: the source, six frames and the target");
  cmd->add_option("--tolerance", a->options.tolerance,
                  "Converged when max |X - X_target| within a voxel of the target is below this (voxels)")
      ->capture_default_str();
  cmd->add_flag("--force", a->options.force, "Write into a folder that is not empty (replacing earlier frames)");
  cmd->add_option("--noise", a->options.noise.amplitude, "The paper's noise on the source's distance field (0.05 = 5%)")
      ->capture_default_str();
  cmd->add_option("--seed", a->options.noise.seed, "Seed of --noise")->capture_default_str();
  auto* dense =
      cmd->add_flag("--dense", a->dense,
                    "Run the lattice on every cell of the grid, as the paper does, instead of the narrow band "
                    "around both surfaces and between them (--noise implies it)");
  cmd->add_flag("--band", a->band, "The narrow band, the default (kept for scripts that name it)")->excludes(dense);
  cmd->callback([&common, a] { runMorph(common, *a); });
}

}  // namespace lbmshape::cli
