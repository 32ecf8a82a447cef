// Options every command shares, the device they run on, and where their
// results go.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "pipeline/compute_device.hpp"

namespace lbmshape::cli {

struct CommonOptions {
  bool verbose = false;
  bool quiet = false;
  bool json = false;                // one JSON object on stdout
  std::string device;               // --device: index, part of a name, or "reference"
  bool validation = false;          // --validate: Khronos validation layer, any message fails the run
  RunsOn distances = RunsOn::Auto;  // --sdf: where the band's distances are computed
  RunsOn surfaces = RunsOn::Auto;   // --extract: where a morph's frames' marching cubes run

  // Where a command's JSON report goes: printed with --json; a jobs file
  // collects one per job instead.
  std::function<void(const nlohmann::json&)> report;

  // The compute device, shared by the jobs of one process, and with it the
  // Vulkan device and its compiled pipelines; it opens what it needs when
  // first asked (compute_device.hpp).
  ComputeDevice& computeDevice() const;
  // Closes the device, if one was opened (ComputeDevice::close).
  void closeDevice() const;

private:
  mutable std::shared_ptr<ComputeDevice> device_;
};

inline bool wantsReference(const CommonOptions& o) { return o.device == "reference"; }

// Writes one JSON document on stdout.
void printJson(const nlohmann::json& document);

}  // namespace lbmshape::cli
