// The morph the pipeline tests run and read back.
#pragma once

#include "lbmshape/pipeline/morph.hpp"

namespace lbmshape::testing {

// On a grid of `resolution` cells, the meshes as they are (no alignment),
// `frames` frames as OBJ files a test reads back, no animation.
inline MorphOptions objFramesMorph(int resolution, int frames)
{
  MorphOptions o;
  o.grid.resolution = resolution;
  o.align = Alignment::None;
  o.format = "obj";
  o.frames = frames;
  o.animation = false;
  return o;
}

}  // namespace lbmshape::testing
