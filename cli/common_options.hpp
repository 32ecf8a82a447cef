// Options every command shares, the device they run on, and where their
// results go.
#pragma once

#include <cctype>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "lbmshape/pipeline/compute_device.hpp"

namespace lbmshape::cli {

struct CommonOptions {
  bool verbose = false;
  bool quiet = false;
  bool json = false;                // one JSON object on stdout
  std::string device;               // --device: index, part of a name, or "reference"
  bool validation = false;          // --validate: Khronos validation layer, any message fails the run
  RunsOn distances = RunsOn::Auto;  // --sdf: where the band's distances are computed
  RunsOn surfaces = RunsOn::Auto;   // --extract: where a morph's frames' marching cubes run

  // A jobs file's first pass (run_command.cpp): a command parses and checks
  // its options, then returns without doing the work.
  bool checkOnly = false;

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

// For an option of an enum type whose values are given by name (case
// ignored): the help shows "{a,b,c}", and anything else is "--option: must
// be a, b or c, not 'x'" (CLI11's own CheckedTransformer shows and accepts
// the enum's numbers too).
template <class Enum>
CLI::Validator namedChoices(std::vector<std::pair<std::string, Enum>> choices)
{
  std::string listed, spoken;
  for (size_t i = 0; i < choices.size(); ++i) {
    listed += (i ? "," : "") + choices[i].first;
    spoken += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i].first;
  }
  return CLI::Validator(
      [choices, spoken](std::string& value) {
        std::string lower = value;
        for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
        for (const auto& [name, choice] : choices)
          if (lower == name) {
            value = std::to_string(int(choice));  // what CLI11 reads an enum from
            return std::string();
          }
        return "must be " + spoken + ", not '" + value + "'";
      },
      "{" + listed + "}");
}

// Writes one JSON document on stdout.
void printJson(const nlohmann::json& document);

}  // namespace lbmshape::cli
