#pragma once

#include <CLI/CLI.hpp>

#include "common_options.hpp"

namespace lbmshape::cli {

// `lbmshape bench`: lattice steps per second on the device and on the CPU
// reference, against the memory-bandwidth roofline; --paper adds Table 1.
void addBenchCommand(CLI::App& app, const CommonOptions& common);

}  // namespace lbmshape::cli
