// lbmshape render, and the previews of denoise and morph: meshes (from
// files, or held in memory) to one PNG picture, drawn on the Vulkan device
// (render/). The options are checked before any mesh is read or any device
// opened.
#pragma once

#include <stop_token>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/pipeline/compute_device.hpp"
#include "lbmshape/render/image.hpp"
#include "lbmshape/render/view.hpp"

namespace lbmshape {

// What the surfaces are coloured by (--color): nothing, their mean
// curvature, or their distance to a reference mesh.
struct Colouring {
  enum class By { Plain, Curvature, Distance } by = By::Plain;
  std::filesystem::path reference;  // for Distance
};
// none, curvature or distance:REF; UsageError naming --color otherwise.
Colouring parseColouring(const std::string& text);
// "WxH"; UsageError naming the size unless both are whole numbers within
// parameter_bounds (pictureSide, picturePixels).
glm::ivec2 parsePictureSize(const std::string& text);

struct RenderOptions {
  std::optional<glm::ivec2> size;  // the whole picture; by default from the number of meshes
  render::View view;
  Colouring colouring;
  bool wireframe = false;
  bool labels = false;
  int columns = 0;       // of the grid of meshes; 0: by their number
  int folderMeshes = 8;  // a folder shows this many of its meshes, evenly chosen, first and last included
  // This call's own stop (a Cancel button for one job among several): a
  // request through its std::stop_source stops this call alone, as
  // interrupt::requestStop stops every call (Interrupted, "stopped: ...").
  std::stop_token stop;
};
void checkRenderOptions(const RenderOptions& options);

// A mesh to draw and its label; the mesh is held by the caller.
struct ShownMesh {
  const TriangleMesh* mesh = nullptr;
  std::string label;
};

// The picture of these meshes, one per cell, under one camera. `figures`,
// when given, receives the picture's size, samples and colour scale.
render::Image drawMeshes(const std::vector<ShownMesh>& meshes, const RenderOptions& options,
                         const ComputeDevice& device, nlohmann::json* figures = nullptr);

// `count` indices into n items at even spacing, the first and the last
// among them (all n when count >= n): the frames a contact sheet shows.
std::vector<size_t> evenlySpaced(size_t n, int count);

// Mesh files, with each folder replaced by its mesh files in name order
// (only its frame_* files where it has any: a morph's folder), evenly
// chosen down to `perFolder` with the first and last kept. InputError for a
// path that is neither, or a folder with no mesh file.
std::vector<std::filesystem::path> meshesToRender(const std::vector<std::filesystem::path>& paths, int perFolder);

// lbmshape render: reads the meshes, draws them, writes `png` (atomically).
// Returns the JSON report.
nlohmann::json renderFiles(const std::vector<std::filesystem::path>& paths, const std::filesystem::path& png,
                           const RenderOptions& options, const ComputeDevice& device);

// Before any work of a job with a preview: the path is a .png (UsageError
// naming --preview) in a folder that can be written (OutputError), unless
// the folder is `createdLater` (a morph's output folder), and the device
// draws (DeviceError; this opens it).
void checkPreview(const std::filesystem::path& png, const ComputeDevice& device,
                  const std::filesystem::path& createdLater = {});
// A labelled preview picture of meshes in memory, seen from `view`,
// written to `png`; returns the milliseconds it took.
double writePreview(const std::vector<ShownMesh>& meshes, const render::View& view, const std::filesystem::path& png,
                    const ComputeDevice& device);

}  // namespace lbmshape
