// Draws the meshes of a picture with a Vulkan graphics pipeline, offscreen
// and headless, on the device the lattice uses (lavapipe included):
// multisampled (4 samples where the device has them), depth-tested, lit by
// render_interface.h's fixed light, and read back into an image. Text comes
// after, on the CPU (text_overlay.hpp).
#pragma once

#include "lbmshape/render/image.hpp"
#include "lbmshape/render/layout.hpp"
#include "lbmshape/render/picture.hpp"

namespace lbmshape::gpu {
class GpuContext;
}

namespace lbmshape::render {

// Throws DeviceError when the device cannot draw, or not a picture of this
// size (its framebuffer limits), or not lines for a wireframe.
Image drawSurfaces(gpu::GpuContext& context, const Picture& picture, const Layout& layout);

// Samples per pixel the device draws this picture with.
int samplesPerPixel(const gpu::GpuContext& context);

}  // namespace lbmshape::render
