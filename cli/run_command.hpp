#pragma once

#include <CLI/CLI.hpp>

#include "common_options.hpp"

namespace lbmshape::cli {

// `lbmshape run jobs.json`: many denoise and morph jobs in one process,
// sharing the device and its compiled pipelines.
void addRunCommand(CLI::App& app, CommonOptions& common);

}  // namespace lbmshape::cli
