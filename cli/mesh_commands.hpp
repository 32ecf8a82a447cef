#pragma once

#include <CLI/CLI.hpp>

#include "common_options.hpp"

namespace lbmshape::cli {

// `lbmshape denoise IN OUT`: smooth a mesh with the lattice Boltzmann scheme.
void addDenoiseCommand(CLI::App& app, const CommonOptions& common);
// `lbmshape morph A B FOLDER`: morph one mesh into another, frame by frame.
void addMorphCommand(CLI::App& app, const CommonOptions& common);
// `lbmshape compare A B`: distances and topology of two meshes.
void addCompareCommand(CLI::App& app, const CommonOptions& common);
// `lbmshape render MESH... OUT.png`: draw meshes into a picture.
void addRenderCommand(CLI::App& app, const CommonOptions& common);
// `lbmshape noise IN OUT`: a copy with Gaussian noise along the normals.
void addNoiseCommand(CLI::App& app, const CommonOptions& common);

}  // namespace lbmshape::cli
