// lbmshape: the command-line front end. It parses the command, runs it, and
// turns every error into one line on stderr and its exit code.
#include <iostream>

#include <CLI/CLI.hpp>

#include "core/error.hpp"

int main(int argc, char** argv)
{
  CLI::App app("lbmshape: surface denoising and morphing with a lattice Boltzmann scheme on Vulkan");
  app.set_version_flag("--version", LBMSHAPE_VERSION);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
