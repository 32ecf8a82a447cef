// lbmshape morph: the level set of a source mesh flows into a target mesh
// (section 5.2 of the paper): the lattice diffuses X (gamma, Eq. 21) while the
// source term F = Cs (X_target - X) (Eq. 22) pulls it towards the target's
// distance field. Frames are written while the lattice goes on.
#pragma once

#include <stop_token>
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "lbmshape/pipeline/compute_device.hpp"
#include "lbmshape/pipeline/frame_writer.hpp"
#include "lbmshape/pipeline/denoise.hpp"

namespace lbmshape {

enum class Alignment {
  None,    // both meshes as they are
  Center,  // the target's bounding-box centre moved onto the source's
  Fit,     // and the target scaled to the source's bounding-box diagonal
};

struct MorphOptions {
  GridOptions grid;  // around both meshes (after alignment)
  Alignment align = Alignment::Fit;
  double cs = 0.1;      // Cs of Eq. 22 (the paper's Fig. 8)
  double gamma = 0.05;  // voxels^2 per step (Fig. 8)
  int frames = 48;
  // Neither given: the morph runs until it arrives at the target, gamma
  // lowered over its second half (pipeline/morph_schedule.hpp). Either
  // given: the paper's scheme, constant gamma for that many steps.
  std::optional<int> stepsPerFrame;
  std::optional<int> steps;    // or the total, spread over the frames
  std::string format = "glb";  // of the frame files: glb, gltf, obj, ply, off, stl
  double fps = 24.0;           // of the animation in morph.glb
  bool animation = true;       // write morph.glb
  bool force = false;          // write into a non-empty folder
  // Frames coloured by mean curvature (--color curvature), on one scale: the
  // target's, as the grid holds it.
  bool colourByCurvature = false;
  // Frames and morph.glb quantized and meshopt-encoded (--compress; glb only).
  GltfCompression compression = GltfCompression::None;
  // A contact sheet (--preview): the source, evenly chosen frames and the
  // target (as placed), labelled.
  std::optional<std::filesystem::path> preview;
  // Converged: max |X - X_target| within a voxel of the target's surface
  // below this (voxels). A morph that arrives runs until it should be; with
  // given steps the lattice stops early once it is.
  double tolerance = 0.25;
  // Each frame's distances to the target, volume and topology in the
  // report's "per_frame" (measured on the frame writer's thread: about as
  // much work as extracting the frame).
  bool frameFigures = true;
  FieldNoise noise;  // on the source's field (the paper's noisy sphere)
  // The lattice on the narrow band around both surfaces and between them
  // (the default), its bricks streaming while the moving surface passes
  // them (pipeline/morph_front.hpp), or with false on every cell of the
  // grid (--dense, the paper's): the band takes less memory and, since it
  // follows the surface, less time (docs/morphing.md).
  bool band = true;
  // Lattice steps between two Ctrl-C checks; by default batches of about a
  // quarter of a second. The frames do not depend on it (for tests).
  std::optional<int> stepsPerBatch;
  // This call's own stop (a Cancel button for one job among several): a
  // request through its std::stop_source stops this call alone, as
  // interrupt::requestStop stops every call (Interrupted, "stopped: ...").
  std::stop_token stop;
};

void checkMorphOptions(const MorphOptions& options);

// Whether the options give the steps (the paper's scheme) or leave the
// morph to run until it arrives.
inline bool stepsGiven(const MorphOptions& o) { return o.steps || o.stepsPerFrame; }
// The steps the options give: --steps, or --steps-per-frame (1 unless given)
// times the frames' intervals.
inline long givenStepCount(const MorphOptions& o)
{
  return o.steps ? long(*o.steps) : long(o.stepsPerFrame.value_or(1)) * (o.frames - 1);
}

// Returns the JSON report. Throws Interrupted (Ctrl-C, checked between
// batches of lattice steps) after writing only complete frames.
nlohmann::json morphFiles(const std::filesystem::path& source, const std::filesystem::path& target,
                          const std::filesystem::path& folder, const MorphOptions& options,
                          const ComputeDevice& device);

// The same morph on meshes in memory: each frame goes to `sink` (on the
// frame writer's thread, in order, while the lattice computes the next),
// nothing to files (the options' animation, preview, format and compression
// do not apply). The meshes are checked as files' are. The report is
// morphFiles', with "folder" and "animation" null.
nlohmann::json morphMeshes(const TriangleMesh& source, const TriangleMesh& target, const MorphOptions& options,
                           const ComputeDevice& device, const FrameSink& sink);

}  // namespace lbmshape
