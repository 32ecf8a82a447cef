#include "bench_command.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>

#include "band_bench.hpp"

#include "lbmshape/bench/denoise_stages.hpp"
#include "lbmshape/bench/lattice_bench.hpp"
#include "lbmshape/bench/memory_bandwidth.hpp"
#include "lbmshape/bench/paper_table.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/parameter_bounds.hpp"
#include "lbmshape/gpu/gpu_context.hpp"
#include "lbmshape/lbm/band_width.hpp"
#include "lbmshape/lbm/lattice_memory.hpp"
#include "lbmshape/lbm/reference_solver.hpp"
#include "lbmshape/lbm/relaxation.hpp"
#include "lbmshape/lbm/vulkan_solver.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "lbmshape/pipeline/smoothing_stop.hpp"
#include "lbmshape/sdf/grid_frame.hpp"

namespace lbmshape::cli {
namespace {

struct BenchOptions {
  std::vector<int> size = {128, 128, 128};
  BenchSettings settings;
  bool paper = false;
  bool band = false;
  std::optional<double> halfWidth;
};

struct SizeResult {
  Extent3 extent;
  std::optional<StepTiming> vulkan;
  StepTiming reference;
};

std::string format(const char* pattern, double a, double b = 0, double c = 0)
{
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
  return buffer;
}

nlohmann::json timingJson(const StepTiming& t, bool withBandwidth)
{
  nlohmann::json j = {{"ms_per_step", t.msPerStep},     {"best_ms_per_step", t.bestMsPerStep},
                      {"first_step_ms", t.firstStepMs}, {"warmup_steps", t.warmupSteps},
                      {"steps_per_run", t.stepsPerRun}, {"mlups", t.mlups}};
  if (withBandwidth) j["gbps"] = t.gbps;
  return j;
}

SizeResult benchSize(const Extent3& extent, gpu::GpuContext* context, const BenchSettings& settings)
{
  SizeResult result{extent, std::nullopt, {}};
  if (context) {
    log::info("timing the Vulkan step on " + extent.toString() + "...");
    VulkanSolver solver(*context, extent);
    result.vulkan = timeSolver(solver, settings);
  }
  log::info("timing the CPU reference on " + extent.toString() + "...");
  ReferenceSolver reference(extent);
  result.reference = timeSolver(reference, referenceSettings(settings));
  return result;
}

// The MLUPS the device's memory allows a step of 152 B: the measured
// bandwidth's, or the lattice's own where it moved more (part of a small
// grid can stay in a cache), so that the lattice is never above its roofline
// because the measurement fell short.
double rooflineMlups(const SizeResult& r, const BandwidthMeasurement& bandwidth)
{
  const double gbps = std::max(bandwidth.gbps, r.vulkan ? r.vulkan->gbps : 0.0);
  return gbps * 1e9 / double(LatticeLayout::bytesPerUpdate) / 1e6;
}

void printSingle(const SizeResult& r, const std::string& device, const BandwidthMeasurement& bandwidth,
                 const BenchSettings& settings)
{
  const double roofline = rooflineMlups(r, bandwidth);
  std::cout << "device: " << device << "\n"
            << "lattice " << r.extent.toString() << ", D3Q19 fp32, " << LatticeLayout::bytesPerUpdate
            << " bytes per update, median of " << settings.runs << " runs of " << settings.steps << " steps\n";
  if (r.vulkan)
    std::cout << format("  vulkan     %8.3f ms/step  %7.1f MLUPS  %6.1f GB/s", r.vulkan->msPerStep, r.vulkan->mlups,
                        r.vulkan->gbps)
              << format("  (first step %.0f ms)\n", r.vulkan->firstStepMs);
  std::cout << format("  reference  %8.3f ms/step  %7.1f MLUPS  %6.1f GB/s", r.reference.msPerStep, r.reference.mlups,
                      r.reference.gbps);
  if (r.reference.stepsPerRun != settings.steps) std::cout << format("  (runs of %.0f steps)", r.reference.stepsPerRun);
  std::cout << "\n";
  std::cout << format("  memory bandwidth %.1f GB/s -> roofline %.0f MLUPS", bandwidth.gbps, roofline) << " ("
            << bandwidth.method << ")\n";
  if (r.vulkan)
    std::cout << format("  vulkan / reference %.2fx, vulkan at %.0f%% of the roofline\n",
                        r.vulkan->mlups / r.reference.mlups, 100.0 * r.vulkan->mlups / roofline);
}

void printPaper(const std::vector<SizeResult>& results, const std::string& device)
{
  std::cout << "Table 1 of the paper (2008: Intel Core 2 6300 CPU, GeForce 8800 GTX GPU) beside this run on " << device
            << ", ms per step:\n";
  std::cout << "  figure    application  lattice        paper CPU  paper GPU  reference     vulkan   vulkan speed-up "
               "vs paper GPU\n";
  for (size_t i = 0; i < results.size(); ++i) {
    const auto& row = paper::table1[i];
    const auto& r = results[i];
    char line[256];
    std::snprintf(line, sizeof line, "  %-9s %-12s %-13s %9.0f  %9.1f  %9.2f  %9s  %s\n", row.figure, row.application,
                  row.size.toString().c_str(), row.cpuMs, row.gpuMs, r.reference.msPerStep,
                  r.vulkan ? format("%.2f", r.vulkan->msPerStep).c_str() : "-",
                  r.vulkan ? format("%.2fx", row.gpuMs / r.vulkan->msPerStep).c_str() : "-");
    std::cout << line;
  }
}

void runBench(const CommonOptions& common, const BenchOptions& options)
{
  // Everything the user chose is checked before the device is touched.
  relaxation::checkGamma(options.settings.gamma, "--gamma");
  if (options.settings.steps < 1 || options.settings.steps > parameter_bounds::maxSteps)
    throw UsageError("--steps must be from 1 to " + std::to_string(parameter_bounds::maxSteps));
  if (options.settings.runs < 1 || options.settings.runs > parameter_bounds::maxBenchRuns)
    throw UsageError("--runs must be from 1 to " + std::to_string(parameter_bounds::maxBenchRuns));
  std::vector<Extent3> sizes;
  if (options.paper) {
    for (const auto& row : paper::table1) sizes.push_back(row.size);
  } else {
    sizes.push_back(Extent3{options.size[0], options.size[1], options.size[2]});
  }
  for (const auto& e : sizes) checkExtent(e);
  // A single size is also timed as a whole denoise at --res of its longest
  // side, which must hold the default margin: refused now, not after the
  // lattice's timings.
  const int leastSide = leastResolution(GridOptions{}.marginVoxels);
  if (!options.paper && std::max({options.size[0], options.size[1], options.size[2]}) < leastSide)
    throw UsageError("--size " + sizes.front().toString() +
                     " is too small: its longest side is also timed as a whole "
                     "denoise at --res, which needs at least " +
                     std::to_string(leastSide));
  if (options.band) {
    const double halfWidth =
        options.halfWidth.value_or(streamingHalfWidth(options.settings.gamma, smoothing_stop::mostSteps));
    if (!(halfWidth >= 1.0 && halfWidth <= 64.0)) throw UsageError("--half-width must be between 1 and 64 voxels");
    runBandBench(common, sizes.front(), options.settings, halfWidth);
    return;
  }

  const ComputeDevice& compute = common.computeDevice();
  for (const auto& e : sizes) compute.checkFits(e);  // against the device's limits, before it is opened
  gpu::GpuContext* context = compute.gpu();          // none with --device reference
  const std::string device = compute.name();
  log::info("measuring memory bandwidth...");
  const BandwidthMeasurement bandwidth = measureMemoryBandwidth(context);
  std::vector<SizeResult> results;
  for (const auto& e : sizes) results.push_back(benchSize(e, context, options.settings));
  // The whole denoise on the same grid (one size only: --paper has five).
  std::optional<nlohmann::json> stages;
  if (!options.paper) {
    const SizeResult& r = results.front();
    log::info("timing a whole denoise on " + r.extent.toString() + "...");
    stages = timeDenoiseStages(std::max({r.extent.nx, r.extent.ny, r.extent.nz}), true, compute,
                               r.vulkan ? r.vulkan->mlups : r.reference.mlups);
  }
  compute.requireCleanValidation();

  auto resultJson = [&](const SizeResult& r) {
    const double roofline = rooflineMlups(r, bandwidth);
    nlohmann::json j = {
        {"device", device},
        {"size", {r.extent.nx, r.extent.ny, r.extent.nz}},
        {"steps", options.settings.steps},
        {"runs", options.settings.runs},
        {"bytes_per_update", LatticeLayout::bytesPerUpdate},
        {"vulkan", r.vulkan ? timingJson(*r.vulkan, true) : nlohmann::json(nullptr)},
        {"reference", timingJson(r.reference, false)},
        {"vulkan_over_reference",
         r.vulkan ? nlohmann::json(r.vulkan->mlups / r.reference.mlups) : nlohmann::json(nullptr)},
        {"roofline_fraction", r.vulkan ? nlohmann::json(r.vulkan->mlups / roofline) : nlohmann::json(nullptr)},
        {"memory_bandwidth", {{"gbps", bandwidth.gbps}, {"method", bandwidth.method}}},
        {"roofline_mlups", roofline}};
    if (context)
      j["startup"] = {{"pipeline_creation_ms", context->pipelineCreationMs()},
                      {"pipeline_cache_loaded_bytes", context->pipelineCacheLoadedBytes()}};
    return j;
  };

  if (!options.paper) {
    if (common.json) {
      nlohmann::json j = resultJson(results.front());
      j["denoise"] = *stages;
      common.report(j);
    } else {
      printSingle(results.front(), device, bandwidth, options.settings);
      std::cout << describeDenoiseStages(*stages);
    }
    return;
  }
  if (common.json) {
    nlohmann::json rows = nlohmann::json::array();
    for (size_t i = 0; i < results.size(); ++i) {
      const auto& row = paper::table1[i];
      nlohmann::json j = resultJson(results[i]);
      j["figure"] = row.figure;
      j["application"] = row.application;
      j["paper"] = {
          {"cpu_ms_per_step", row.cpuMs}, {"gpu_ms_per_step", row.gpuMs}, {"texture_megabytes", row.textureMegabytes}};
      rows.push_back(j);
    }
    common.report({{"device", device}, {"table1", rows}});
  } else {
    printPaper(results, device);
  }
}

}  // namespace

void addBenchCommand(CLI::App& app, const CommonOptions& common)
{
  auto options = std::make_shared<BenchOptions>();
  auto* bench = app.add_subcommand("bench", "Time the lattice step on the device and on the CPU reference");
  auto* size = bench->add_option("--size", options->size, "Lattice size NX,NY,NZ")
                   ->delimiter(',')
                   ->expected(3)
                   ->capture_default_str();
  bench->add_option("--steps", options->settings.steps, "Steps per timed run")->capture_default_str();
  bench->add_option("--runs", options->settings.runs, "Timed runs; the median is reported")->capture_default_str();
  bench->add_option("--gamma", options->settings.gamma, "Diffusion coefficient, voxels^2 per step")
      ->capture_default_str();
  auto* paper =
      bench
          ->add_flag("--paper", options->paper, "Run the five lattices of the paper's Table 1 and print it beside ours")
          ->excludes(size);
  auto* band =
      bench
          ->add_flag("--band", options->band,
                     "Time the narrow-band lattice, on the band a denoise would make around a sphere in the grid")
          ->excludes(paper);
  bench
      ->add_option("--half-width", options->halfWidth,
                   "With --band: voxels each side of the surface that stream (default: an isotropic denoise's, 6 at "
                   "the default gamma; a default denoise's is 8, for smoothing that may be twiced)")
      ->needs(band);
  bench->callback([&common, options] { runBench(common, *options); });
}

}  // namespace lbmshape::cli
