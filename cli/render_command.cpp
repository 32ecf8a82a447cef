#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"
#include "mesh_commands.hpp"
#include "lbmshape/pipeline/render_job.hpp"

namespace lbmshape::cli {
namespace {

struct RenderArguments {
  std::vector<std::string> paths;  // meshes or folders, then the picture
  std::string size, view = "front", colour = "none";
  RenderOptions options;
};

void runRender(const CommonOptions& common, RenderArguments& a)
{
  if (a.paths.size() < 2) throw UsageError("render needs at least one mesh (or folder) and the picture to write");
  const std::filesystem::path png = a.paths.back();
  const std::vector<std::filesystem::path> meshes(a.paths.begin(), a.paths.end() - 1);
  if (!a.size.empty()) a.options.size = parsePictureSize(a.size);
  a.options.view = render::parseView(a.view);
  a.options.colouring = parseColouring(a.colour);
  checkRenderOptions(a.options);  // before the device is opened
  const nlohmann::json report = renderFiles(meshes, png, a.options, common.computeDevice());
  common.report(report);
  if (!common.json)
    log::info("wrote " + png.string() + " (" + std::to_string(report["size"][0].get<int>()) + "x" +
              std::to_string(report["size"][1].get<int>()) + ", " + std::to_string(report["meshes"].size()) +
              (report["meshes"].size() == 1 ? " mesh" : " meshes") + ") in " +
              std::to_string(int(report["ms"]["total"].get<double>())) + " ms");
}

}  // namespace

void addRenderCommand(CLI::App& app, const CommonOptions& common)
{
  auto a = std::make_shared<RenderArguments>();
  auto* cmd = app.add_subcommand("render",
                                 "Draw meshes side by side into a PNG picture, on the Vulkan device, with no display");
  cmd->add_option("paths", a->paths,
                  "Meshes (.obj .ply .off .stl .gltf .glb) or folders of frames, then the picture to write (.png)")
      ->required()
      ->expected(2, -1);
  cmd->add_option("--size", a->size, "Picture size WIDTHxHEIGHT in pixels (default: 512 per mesh, fewer for many)");
  cmd->add_option("--view", a->view, "front, side, top, iso, or AZIMUTH,ELEVATION in degrees")->capture_default_str();
  cmd->add_option("--color", a->colour, "none, curvature (mean curvature), or distance:REFERENCE_MESH")
      ->capture_default_str();
  cmd->add_flag("--wireframe", a->options.wireframe, "Draw the triangles' edges over the surface");
  cmd->add_flag("--labels", a->options.labels, "Write each mesh's file name under it");
  cmd->add_option("--columns", a->options.columns,
                  "Meshes per row (0: one row up to four, then about twice as wide as high)")
      ->capture_default_str();
  cmd->add_option("--count", a->options.folderMeshes,
                  "Meshes shown from each folder, evenly chosen, first and last included")
      ->capture_default_str();
  cmd->callback([&common, a] { runRender(common, *a); });
}

}  // namespace lbmshape::cli
