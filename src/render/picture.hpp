// What one picture shows: meshes side by side, each in its own cell of a
// grid, all under one camera and one scale, with optional labels and a
// colour legend.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/render/colour_map.hpp"
#include "lbmshape/render/view.hpp"

namespace lbmshape::render {

struct Panel {
  const TriangleMesh* mesh = nullptr;  // held by the caller while drawing
  std::vector<glm::vec3> colours;      // per vertex, 0..1; empty: the plain surface colour
  std::string label;                   // drawn under the mesh when the picture has labels
};

struct Picture {
  int width = 0, height = 0;  // pixels, legend and labels included
  View view;
  bool wireframe = false;
  bool labels = false;
  int columns = 0;  // of the grid of cells; 0: layout.hpp's choice
  std::vector<Panel> panels;
  std::optional<Legend> legend;  // drawn along the bottom when set
};

// The colour of a surface that is not coloured by a value: a light blue-grey
// that the white background sets off.
inline glm::vec3 plainSurfaceColour() { return {0.70f, 0.74f, 0.80f}; }

}  // namespace lbmshape::render
