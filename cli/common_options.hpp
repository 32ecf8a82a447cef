// Options every command shares, and opening the device they ask for.
#pragma once

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "gpu/gpu_context.hpp"

namespace lbmshape::cli {

struct CommonOptions {
  bool verbose = false;
  bool quiet = false;
  bool json = false;        // one JSON object on stdout
  std::string device;       // --device: index, part of a name, or "reference"
  bool validation = false;  // --validate: Khronos validation layer, any message fails the run
};

inline bool wantsReference(const CommonOptions& o) { return o.device == "reference"; }

// The Vulkan device for a command (never for --device reference).
std::unique_ptr<gpu::GpuContext> openDevice(const CommonOptions& options);

// With validation on, a run that drew any validation message fails (exit 5).
void requireCleanValidation(const gpu::GpuContext& context);

// Writes one JSON document on stdout.
void printJson(const nlohmann::json& document);

}  // namespace lbmshape::cli
