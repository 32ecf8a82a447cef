#pragma once

#include <CLI/CLI.hpp>

#include "common_options.hpp"

namespace lbmshape::cli {

// `lbmshape info`: the Vulkan devices and which one lbmshape would use.
void addInfoCommand(CLI::App& app, const CommonOptions& common);

}  // namespace lbmshape::cli
