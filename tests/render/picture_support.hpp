// Drawing test pictures on the tests' shared device, and measuring them.
#pragma once

#include <filesystem>
#include <vector>

#include "lbmshape/gpu/gpu_context.hpp"
#include "lbmshape/render/image.hpp"
#include "lbmshape/render/layout.hpp"
#include "lbmshape/render/picture.hpp"

namespace lbmshape::testing {

// The meshes side by side, no labels, plain colours unless given.
render::Picture plainPicture(const std::vector<const TriangleMesh*>& meshes, int width, int height,
                             const char* view = "front");
render::Image draw(gpu::GpuContext& gpu, const render::Picture& picture);

// Whether a pixel shows something other than the background.
bool covered(const render::Image& image, int x, int y);
// Covered pixels in the rectangle.
long coveredPixels(const render::Image& image, const render::Rect& area);

render::Image readPng(const std::filesystem::path& file);

}  // namespace lbmshape::testing
