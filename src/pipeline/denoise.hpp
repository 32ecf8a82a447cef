// lbmshape denoise: mesh in, signed distance field, lattice Boltzmann
// smoothing (section 5.1 of the paper), marching cubes, mesh out.
#pragma once

#include <stop_token>
#include <cstdint>
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "lbmshape/mesh/gltf_compression.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/pipeline/compute_device.hpp"
#include "lbmshape/pipeline/field_noise.hpp"
#include "lbmshape/sdf/grid_frame.hpp"
#include "lbmshape/surface/triangle_relaxation.hpp"

namespace lbmshape {

// How the grid is placed around the mesh.
struct GridOptions {
  int resolution = 128;         // cells along the longest side, margins included
  std::optional<double> voxel;  // or: the voxel size, in the mesh's units
  double marginVoxels = 4.0;    // empty cells around the mesh's bounding box
};

enum class Smoothing {
  Isotropic,         // one gamma everywhere
  Anisotropic,       // the paper's gamma = gamma0 + kappa (Eq. 20)
  PreserveFeatures,  // gamma falling at sharp edges (adaptive_gamma.hpp)
};

struct DenoiseOptions {
  GridOptions grid;
  // Lattice steps; none given: as many as the noise needs, from 3 to 7
  // (--steps auto, pipeline/smoothing_stop.hpp). The paper's Figs. 4-6: 7.
  std::optional<int> steps;
  // Or the smoothing's radius in the mesh's units (--radius): the steps
  // whose diffusion reaches a variance of (radius / voxel)^2, the same
  // smoothing at any resolution (pipeline/smoothing_radius.hpp). Not with
  // `steps`.
  std::optional<double> radius;
  double gamma = 0.2;  // voxels^2 per step
  // Feature-preserving by default: ahead of OpenVDB's mean-curvature filter
  // more often than isotropic smoothing, which rounds sharp edges (with
  // twicing where it pays, 32 of 33 noisy cases; docs/denoising.md, "How
  // good it is").
  Smoothing smoothing = Smoothing::PreserveFeatures;
  // The smoothed field shifted by a constant so that it encloses the
  // volume the input did (surface/volume_keeping.hpp); off: the paper's
  // scheme, which shrinks the surface as mean-curvature flow does.
  bool keepVolume = true;
  // The smoothing twiced, 2 S X - S^2 X (twicing.hpp): thin parts that
  // mean curvature flow erodes kept, noise removed as well or better, at
  // about twice the lattice steps (--twicing, --no-twicing;
  // docs/denoising.md). Unset: twiced where it pays, when the default
  // smoothing's steps are chosen and the noise needs at least
  // twicingFromSteps of them (twicing.hpp).
  std::optional<bool> twicing;
  // Rounds of tangential relaxation of marching cubes' triangles
  // (surface/triangle_relaxation.hpp): the slivers evened out, the surface
  // left where it is; 0: marching cubes' own triangles (--relax).
  int relaxRounds = defaultRelaxationRounds;
  FieldNoise noise;  // the paper's noise on the distance field, off by default
  // The lattice on the narrow band around the surface (band/), or on every
  // cell of the grid (the paper's, and the reference the band is tested
  // against). The paper's field noise is defined over the whole grid, so
  // --noise runs on the grid.
  bool dense = false;
  bool replaceInput = false;  // the output may be the input file (--force)
  // The output's vertices coloured by mean curvature (--color curvature;
  // COLOR_0 in glTF, "v x y z r g b" in OBJ).
  bool colourByCurvature = false;
  // The output quantized and meshopt-encoded (--compress; .glb only).
  GltfCompression compression = GltfCompression::None;
  // This call's own stop (a Cancel button for one job among several): a
  // request through its std::stop_source stops this call alone, as
  // interrupt::requestStop stops every call (Interrupted, "stopped: ...").
  std::stop_token stop;
  // A picture of the input and the output side by side (--preview).
  std::optional<std::filesystem::path> preview;
};

struct DenoiseResult {
  TriangleMesh mesh;
  nlohmann::json report;  // counts, grid, timings, volume change, MLUPS
};

// Checks the options (UsageError) before any work; a preview's name too.
void checkDenoiseOptions(const DenoiseOptions& options);
// denoiseFile's UsageErrors, which need no file and no device: the options,
// and the output's format with its compression and colours. What `run
// --check` finds of a denoise job.
void checkDenoiseFileArguments(const std::filesystem::path& output, const DenoiseOptions& options);
// The checks of the grid and noise options, which morph shares.
void checkGridAndNoise(const GridOptions& grid, const FieldNoise& noise);

// UsageError unless `output` is a format that holds vertex colours (glb,
// gltf, obj): for --color curvature, before any work.
void requireColourFormat(const std::filesystem::path& output, const std::string& what);
// Colours the mesh's vertices by mean curvature (render/curvature_colours)
// and says so on stderr; returns the scale.
double colourByCurvature(TriangleMesh& mesh);
// Says on stderr what the colours of --color curvature mean: the map over
// ±scale, `whose` 95th percentile of |H|.
void reportCurvatureColours(double scale, const std::string& whose);

// The grid for a mesh.
GridFrame placeGrid(const Bounds& bounds, const GridOptions& options);

// Smooths a mesh in memory: the grid around it, its signed distance, the
// lattice, marching cubes (and the curvature colours if asked; the options
// about files, compression and --preview have no effect here). `name` names
// the mesh in errors; the mesh is checked as a file's is (InputError for an
// index out of range, a coordinate that is not finite, a flat surface). The report: grid, device, gamma, steps, steps_chosen,
// steps_run, noise_amplitude_voxels, noise_steps, smoothing, keep_volume,
// volume_shift_voxels, noise, lattice, mlups, curvature_scale and ms
// (noise_amplitude, sdf, setup, lbm, extract, total).
DenoiseResult denoiseMesh(const TriangleMesh& mesh, const std::string& name, const DenoiseOptions& options,
                          const ComputeDevice& device);

// Reads `input`, smooths it as denoiseMesh does, and writes `output` (format
// by extension). The output path is checked first, so a bad extension or
// folder costs nothing. The report adds the input and output meshes' figures
// and paths, volume_change, preview, and the read and write stages.
DenoiseResult denoiseFile(const std::filesystem::path& input, const std::filesystem::path& output,
                          const DenoiseOptions& options, const ComputeDevice& device);

}  // namespace lbmshape
