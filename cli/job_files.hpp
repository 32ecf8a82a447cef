// The files the jobs of a jobs file read and write, compared across jobs:
// two jobs writing one file are refused, and a job that reads what another
// writes after it, or in another part of --shard, is warned about.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lbmshape::cli {

// Two jobs writing the same file (the second would replace the first's
// result), however its path is spelled, or one writing into another's
// folder of frames, are refused, naming both jobs (UsageError). Then warns,
// naming both jobs, of each job of this part (`inThisPart`, by 1-based job
// number) that reads a file (a mesh, or a frame in a morph's folder) that a
// later job of the file writes, or a job of another part: it would read
// what was there before, or nothing. In one process the jobs run in the
// file's order; the parts of --shard run side by side.
void checkJobFiles(const nlohmann::json& jobs, const std::filesystem::path& file,
                   const std::function<bool(size_t)>& inThisPart, bool sharded);

}  // namespace lbmshape::cli
