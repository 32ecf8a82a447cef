// One job of a jobs file (`lbmshape run`) as the command line it stands for.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace lbmshape::cli {

// The command, its positional paths (relative to `base`, the jobs file's
// folder), then every other key as --key=VALUE, or --key for a flag set to
// true. `commands` holds the commands' definitions: each key must be a long
// option of the job's command, and its value of the JSON type the option
// takes: true/false for a flag, a number for a numeric option (a whole
// number where it counts something; 96.0 is 96), a string for the others;
// null leaves the option at its default. Throws UsageError naming the key.
std::vector<std::string> jobCommandLine(const nlohmann::json& job, const std::filesystem::path& base,
                                        const CLI::App& commands);

}  // namespace lbmshape::cli
