#include "lbmshape/pipeline/render_job.hpp"

#include <algorithm>
#include <map>
#include <cstdlib>

#include "lbmshape/core/atomic_file.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/parameter_bounds.hpp"
#include "lbmshape/core/stopwatch.hpp"
#include "lbmshape/gpu/gpu_context.hpp"
#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_validation.hpp"
#include "lbmshape/pipeline/frame_writer.hpp"
#include "lbmshape/pipeline/stage_clock.hpp"
#include "lbmshape/render/colour_map.hpp"
#include "lbmshape/render/curvature_colours.hpp"
#include "lbmshape/render/layout.hpp"
#include "lbmshape/render/picture.hpp"
#include "lbmshape/render/png_file.hpp"
#include "lbmshape/render/surface_renderer.hpp"
#include "lbmshape/render/surface_values.hpp"
#include "lbmshape/render/text_overlay.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"

namespace fs = std::filesystem;

namespace lbmshape {
namespace {

// Whole positive number, or nothing.
std::optional<int> wholeNumber(const std::string& text)
{
  if (text.empty() || text.size() > 9 ||
      !std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); }))
    return std::nullopt;
  return std::atoi(text.c_str());
}

// The legend and each mesh's colours for the chosen colouring: one scale
// for every mesh of the picture, so that equal colours mean equal values.
std::optional<render::Legend> colourPanels(std::vector<render::Panel>& panels, const Colouring& colouring,
                                           const TriangleMesh* reference)
{
  if (colouring.by == Colouring::By::Plain) return std::nullopt;
  std::vector<std::vector<double>> values;
  std::optional<TriangleBvh> tree;
  if (colouring.by == Colouring::By::Distance) tree.emplace(*reference, TriangleBvh::Queries::ClosestOnly);
  std::vector<double> all;
  for (const render::Panel& p : panels) {
    values.push_back(colouring.by == Colouring::By::Curvature ? render::vertexMeanCurvature(*p.mesh)
                                                              : render::vertexDistances(*p.mesh, *tree));
    all.insert(all.end(), values.back().begin(), values.back().end());
  }
  render::Legend legend;
  if (colouring.by == Colouring::By::Curvature) {
    // One scale over every mesh of the picture, the rule of --color curvature.
    const double scale = render::curvatureScale(all);
    legend = {"mean curvature (1/unit), 95% of vertices within the scale", -scale, scale, true};
  } else {
    const double scale = render::quantile(all, 0.99, true);
    legend = {"distance to " + colouring.reference.filename().string() + " (mesh units)", 0.0, scale > 0 ? scale : 1.0,
              false};
  }
  for (size_t i = 0; i < panels.size(); ++i) {
    panels[i].colours.resize(values[i].size());
    for (size_t v = 0; v < values[i].size(); ++v) panels[i].colours[v] = render::legendColour(legend, values[i][v]);
  }
  return legend;
}

std::vector<fs::path> meshFilesIn(const fs::path& folder)
{
  std::vector<fs::path> files;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec))
    if (entry.is_regular_file(ec) && meshFormatOf(entry.path())) files.push_back(entry.path());
  if (ec) throw InputError("cannot list the folder " + folder.string() + ": " + ec.message());
  if (std::any_of(files.begin(), files.end(), FrameWriter::isFrameName))
    std::erase_if(files, [](const fs::path& f) { return !FrameWriter::isFrameName(f); });
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

std::vector<size_t> evenlySpaced(size_t n, int count)
{
  std::vector<size_t> chosen;
  if (n <= size_t(std::max(count, 0))) {
    for (size_t i = 0; i < n; ++i) chosen.push_back(i);
    return chosen;
  }
  for (int i = 0; i < count; ++i)
    chosen.push_back(count == 1 ? 0 : (size_t(i) * (n - 1) + size_t(count - 1) / 2) / size_t(count - 1));
  return chosen;
}

Colouring parseColouring(const std::string& text)
{
  if (text == "none") return {};
  if (text == "curvature") return {Colouring::By::Curvature, {}};
  const std::string prefix = "distance:";
  if (text.rfind(prefix, 0) == 0 && text.size() > prefix.size())
    return {Colouring::By::Distance, text.substr(prefix.size())};
  throw UsageError(nameOf(Parameter::Colouring) + " '" + text + "' is not none, curvature or distance:REFERENCE_MESH");
}

void checkPictureSize(glm::ivec2 size, const std::string& given)
{
  namespace bounds = parameter_bounds;
  if (size.x < bounds::minPictureSide || size.y < bounds::minPictureSide || size.x > bounds::maxPictureSide ||
      size.y > bounds::maxPictureSide || long(size.x) * long(size.y) > bounds::maxPicturePixels)
    throw UsageError(nameOf(Parameter::Size) + " " + given + " is outside the pictures lbmshape draws: each side " +
                     std::to_string(bounds::minPictureSide) + " to " + std::to_string(bounds::maxPictureSide) +
                     " pixels, at most " + std::to_string(bounds::maxPicturePixels) + " pixels in all (4096x4096)");
}

glm::ivec2 parsePictureSize(const std::string& text)
{
  const size_t x = text.find_first_of("xX");
  const std::optional<int> w = x == std::string::npos ? std::nullopt : wholeNumber(text.substr(0, x));
  const std::optional<int> h = x == std::string::npos ? std::nullopt : wholeNumber(text.substr(x + 1));
  if (!w || !h)
    throw UsageError(nameOf(Parameter::Size) + " '" + text + "' is not WIDTHxHEIGHT in pixels (for example 1024x768)");
  checkPictureSize({*w, *h}, text);
  return {*w, *h};
}

void checkRenderOptions(const RenderOptions& o)
{
  if (o.folderMeshes < 1 || o.folderMeshes > parameter_bounds::maxFolderMeshes)
    throw UsageError(nameOf(Parameter::Count) + " must be 1 to " + std::to_string(parameter_bounds::maxFolderMeshes));
  if (o.columns < 0 || o.columns > parameter_bounds::maxFolderMeshes)
    throw UsageError(nameOf(Parameter::Columns) + " must be 0 (automatic) to " +
                     std::to_string(parameter_bounds::maxFolderMeshes));
  if (o.size) checkPictureSize(*o.size, std::to_string(o.size->x) + "x" + std::to_string(o.size->y));
}

render::Image drawMeshes(const std::vector<ShownMesh>& meshes, const RenderOptions& o, const ComputeDevice& device,
                         nlohmann::json* figures)
{
  const interrupt::CallStop ownStop(o.stop);
  for (const ShownMesh& m : meshes) {
    if (!m.mesh) throw UsageError("drawMeshes: the mesh to show as \"" + m.label + "\" is null");
    requireWellFormed(*m.mesh, m.label.empty() ? "a mesh to show" : m.label);
    if (!m.mesh->colours.empty() && m.mesh->colours.size() != m.mesh->positions.size())
      throw InputError("cannot draw " + m.label + ": it has " + std::to_string(m.mesh->colours.size()) +
                       " colours for " + std::to_string(m.mesh->positions.size()) + " vertices");
  }
  const ComputeDevice::Turn turn = device.takeTurn();
  render::Picture picture;
  picture.view = o.view;
  picture.wireframe = o.wireframe;
  picture.labels = o.labels;
  picture.columns = o.columns;
  // A mesh's own colours (a coloured scan) show as they are, unless
  // --color asks for something else.
  for (const ShownMesh& m : meshes) picture.panels.push_back({m.mesh, m.mesh->colours, m.label});
  std::optional<TriangleMesh> reference;
  if (o.colouring.by == Colouring::By::Distance) reference = readMesh(o.colouring.reference);
  Stopwatch colouring;
  picture.legend = colourPanels(picture.panels, o.colouring, reference ? &*reference : nullptr);
  const double colouringMs = colouring.ms();
  const glm::ivec2 size =
      o.size.value_or(render::defaultPictureSize(int(meshes.size()), o.labels, picture.legend.has_value(), o.columns));
  picture.width = size.x, picture.height = size.y;

  const render::Layout layout = render::arrange(picture);
  for (const render::Rect& cell : layout.meshCells)
    if (cell.width < parameter_bounds::minPictureSide || cell.height < parameter_bounds::minPictureSide)
      throw UsageError(nameOf(Parameter::Size) + " " + std::to_string(picture.width) + "x" +
                       std::to_string(picture.height) + " leaves cells of " + std::to_string(cell.width) + "x" +
                       std::to_string(cell.height) + " pixels for " + std::to_string(meshes.size()) + " meshes in " +
                       std::to_string(layout.columns) + " columns; each needs at least " +
                       std::to_string(parameter_bounds::minPictureSide) + " pixels each way: give a larger " +
                       nameOf(Parameter::Size) + " or other " + nameOf(Parameter::Columns));
  gpu::GpuContext& context = device.drawingContext();
  Stopwatch drawing;
  render::Image image = render::drawSurfaces(context, picture, layout);
  const double drawMs = drawing.ms();
  for (size_t i = 0; i < layout.labelCells.size(); ++i)
    render::drawLabel(image, layout.labelCells[i], picture.panels[i].label, layout.textScale);
  if (picture.legend) render::drawLegend(image, *layout.legend, *picture.legend, layout.textScale);
  device.requireCleanValidation();
  if (figures) {
    *figures = {{"size", {picture.width, picture.height}},
                {"samples_per_pixel", render::samplesPerPixel(context)},
                {"columns", layout.columns},
                {"rows", layout.rows},
                {"draw_ms", drawMs},
                {"colour_ms", colouringMs}};
    if (picture.legend)
      (*figures)["legend"] = {
          {"title", picture.legend->title}, {"low", picture.legend->low}, {"high", picture.legend->high}};
  }
  return image;
}

std::vector<fs::path> meshesToRender(const std::vector<fs::path>& paths, int perFolder)
{
  std::vector<fs::path> files;
  for (const fs::path& path : paths) {
    std::error_code ec;
    if (!fs::is_directory(path, ec)) {
      files.push_back(path);  // the reader says what is wrong with it, if anything
      continue;
    }
    const std::vector<fs::path> inFolder = meshFilesIn(path);
    if (inFolder.empty()) throw InputError("the folder " + path.string() + " holds no mesh file");
    for (size_t i : evenlySpaced(inFolder.size(), perFolder)) files.push_back(inFolder[i]);
  }
  return files;
}

// Each file's name, and where two shown files share one (two morphs'
// folders: frame_0000.glb each), its folder's name before it, so that the
// labels tell them apart.
std::vector<std::string> panelLabels(const std::vector<fs::path>& files)
{
  std::map<std::string, int> uses;
  for (const fs::path& f : files) ++uses[f.filename().string()];
  std::vector<std::string> labels;
  for (const fs::path& f : files) {
    const std::string name = f.filename().string();
    const std::string folder = f.parent_path().filename().string();
    labels.push_back(uses[name] > 1 && !folder.empty() ? folder + "/" + name : name);
  }
  return labels;
}

nlohmann::json renderFiles(const std::vector<fs::path>& paths, const fs::path& png, const RenderOptions& o,
                           const ComputeDevice& device)
{
  const interrupt::CallStop ownStop(o.stop);
  checkRenderOptions(o);
  render::requirePngPath(png, "the picture");
  const ComputeDevice::Turn turn = device.takeTurn();
  const std::vector<fs::path> files = meshesToRender(paths, o.folderMeshes);
  if (files.size() > size_t(parameter_bounds::maxFolderMeshes))
    throw UsageError("a picture shows at most " + std::to_string(parameter_bounds::maxFolderMeshes) + " meshes; " +
                     std::to_string(files.size()) + " were given");
  AtomicFile file(png);  // an unwritable path fails here, before the meshes are read
  StageClock clock;
  std::vector<TriangleMesh> meshes;
  clock.time("read", [&] {
    // A morph's frame may hold no triangles (the shape passing through
    // nothing): drawn as an empty panel, as its --preview does.
    for (const fs::path& f : files) meshes.push_back(readMesh(f, EmptyMesh::Allowed, FlatMesh::Allowed));
  });
  std::vector<ShownMesh> shown;
  nlohmann::json panels = nlohmann::json::array();
  const std::vector<std::string> labels = panelLabels(files);
  for (size_t i = 0; i < files.size(); ++i) {
    shown.push_back({&meshes[i], labels[i]});
    panels.push_back({{"path", files[i].string()}, {"label", labels[i]}, {"triangles", meshes[i].triangleCount()}});
  }
  nlohmann::json figures;
  const render::Image image = clock.time("draw", [&] { return drawMeshes(shown, o, device, &figures); });
  clock.time("write", [&] { render::writePng(image, file); });
  // The device that drew, which for --device reference is the best Vulkan
  // device there is, not the solver.
  nlohmann::json report = {{"command", "render"},
                           {"output", png.string()},
                           {"meshes", panels},
                           {"device", device.drawingContext().description().name}};
  report.update(figures);
  report["ms"] = clock.toJson();
  return report;
}

void checkPreview(const fs::path& png, const ComputeDevice& device, const fs::path& createdLater)
{
  render::requirePngPath(png, nameOf(Parameter::Preview));
  const ComputeDevice::Turn turn = device.takeTurn();
  device.drawingContext().requireDrawing(", or leave out " + nameOf(Parameter::Preview));
  std::error_code ec;
  if (!createdLater.empty() && fs::weakly_canonical(png.parent_path().empty() ? "." : png.parent_path(), ec) ==
                                   fs::weakly_canonical(createdLater, ec))
    return;
  AtomicFile probe(png);  // created and, uncommitted, removed again
}

double writePreview(const std::vector<ShownMesh>& meshes, const render::View& view, const fs::path& png,
                    const ComputeDevice& device)
{
  Stopwatch watch;
  RenderOptions o;
  o.labels = true;
  o.view = view;
  const render::Image image = drawMeshes(meshes, o, device);
  AtomicFile file(png);
  render::writePng(image, file);
  log::verbose("preview " + png.string() + " in " + std::to_string(int(watch.ms())) + " ms");
  return watch.ms();
}

}  // namespace lbmshape
