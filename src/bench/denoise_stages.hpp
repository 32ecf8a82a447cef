// A whole denoise beside the bench's lattice: how much of a real job the
// lattice stage is, and how near its speed comes to the bench's once
// uploads, submissions and read-backs count.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "lbmshape/pipeline/compute_device.hpp"

namespace lbmshape {

// Denoises a noisy sphere in memory with the defaults at --res `resolution`
// (a grid of that many cells a side), on the grid (`dense`) or on the band:
// an icosphere of 81,920 triangles, the size of a scan of 40k vertices, with
// Gaussian vertex noise of 0.3 mean edge lengths, so that the automatic steps
// have noise to remove. Returns {"mesh", "res", "lattice", "steps_run", "ms"
// (per stage), "mlups", "lattice_share" (lbm ms over the total),
// "mlups_over_bench" (mlups over `benchMlups`, the same cells' speed in the
// bench's timed runs)}.
nlohmann::json timeDenoiseStages(int resolution, bool dense, const ComputeDevice& device, double benchMlups);

// One line for the bench's text output.
std::string describeDenoiseStages(const nlohmann::json& stages);

}  // namespace lbmshape
