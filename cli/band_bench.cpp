#include "band_bench.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>

#include "lbmshape/bench/band_bench.hpp"
#include "lbmshape/bench/denoise_stages.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/gpu/gpu_context.hpp"
#include "lbmshape/lbm/band_reference_solver.hpp"
#include "lbmshape/lbm/band_vulkan_solver.hpp"

namespace lbmshape::cli {
namespace {

nlohmann::json timingJson(const BandStepTiming& t)
{
  return {{"ms_per_step", t.perStep.msPerStep},     {"best_ms_per_step", t.perStep.bestMsPerStep},
          {"first_step_ms", t.perStep.firstStepMs}, {"warmup_steps", t.perStep.warmupSteps},
          {"steps_per_run", t.perStep.stepsPerRun}, {"mlups", t.perStep.mlups},
          {"stored_mlups", t.storedMlups}};
}

void printTiming(const char* name, const BandStepTiming& t)
{
  std::printf(
      "  %-10s %8.3f ms/step  %7.1f MLUPS on stepped cells  %7.1f on stored cells  (first step %.0f ms, runs of %d "
      "steps)\n",
      name, t.perStep.msPerStep, t.perStep.mlups, t.storedMlups, t.perStep.firstStepMs, t.perStep.stepsPerRun);
}

}  // namespace

void runBandBench(const CommonOptions& common, const Extent3& extent, const BenchSettings& settings, double halfWidth)
{
  const ComputeDevice& compute = common.computeDevice();
  const BandBenchCase band =
      sphereBand(extent, halfWidth, [&](const BrickSet& b) { compute.checkBandFits(b, false, false); });
  const BrickSet& bricks = band.field.bricks();
  gpu::GpuContext* context = compute.gpu();  // none with --device reference
  std::optional<BandStepTiming> vulkan;
  if (context) {
    log::info("timing the Vulkan band step on " + extent.toString() + "...");
    BandVulkanSolver solver(*context, band.field.sharedBricks());
    vulkan = timeBandSolver(solver, band, settings);
  }
  log::info("timing the CPU band reference on " + extent.toString() + "...");
  BandReferenceSolver reference(band.field.sharedBricks());
  const BandStepTiming cpu = timeBandSolver(reference, band, referenceSettings(settings));
  // A denoise counts MLUPS on every stored cell: compared with the same.
  log::info("timing a whole denoise on " + extent.toString() + "...");
  const nlohmann::json stages = timeDenoiseStages(std::max({extent.nx, extent.ny, extent.nz}), false, compute,
                                                  vulkan ? vulkan->storedMlups : cpu.storedMlups);
  compute.requireCleanValidation();

  const double bytesPerCell = BandVulkanSolver::deviceBytesPerCell(false, false);
  if (common.json) {
    common.report({{"device", compute.name()},
                   {"size", {extent.nx, extent.ny, extent.nz}},
                   {"steps", settings.steps},
                   {"runs", settings.runs},
                   {"band",
                    {{"half_width", halfWidth},
                     {"bricks", bricks.activeCount()},
                     {"stored_cells", bricks.storedCells()},
                     {"stepped_cells", band.steppedCells},
                     {"streaming_cells", band.streamingCells},
                     {"fraction_of_grid", double(bricks.storedCells()) / double(extent.cells())},
                     {"device_bytes_per_stored_cell", bytesPerCell}}},
                   {"vulkan", vulkan ? timingJson(*vulkan) : nlohmann::json(nullptr)},
                   {"reference", timingJson(cpu)},
                   {"vulkan_over_reference",
                    vulkan ? nlohmann::json(vulkan->perStep.mlups / cpu.perStep.mlups) : nlohmann::json(nullptr)},
                   {"denoise", stages}});
    return;
  }
  std::cout << "device: " << compute.name() << "\n";
  std::printf(
      "narrow band in %s around a sphere: %zu bricks, %zu stored cells (%.1f%% of the grid), %zu stepped, "
      "%zu streaming (half width %.0f); %.1f bytes a stored cell on the device; median of %d runs of %d steps\n",
      extent.toString().c_str(), bricks.activeCount(), bricks.storedCells(),
      100.0 * double(bricks.storedCells()) / double(extent.cells()), band.steppedCells, band.streamingCells, halfWidth,
      bytesPerCell, settings.runs, settings.steps);
  if (vulkan) printTiming("vulkan", *vulkan);
  printTiming("reference", cpu);
  if (vulkan) std::printf("  vulkan / reference %.2fx\n", vulkan->perStep.mlups / cpu.perStep.mlups);
  std::cout << describeDenoiseStages(stages);
}

}  // namespace lbmshape::cli
