// What a morph's lattice holds, on the whole grid or on the narrow band:
// the two signed distance fields, the solver with the morph force, the
// field of each frame and how far it still is from the target. morph.cpp
// runs the frames the same way on either.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>

#include <nlohmann/json.hpp>

#include "lbmshape/lbm/stepping_solver.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/pipeline/compute_device.hpp"
#include "lbmshape/pipeline/frame_writer.hpp"
#include "lbmshape/pipeline/morph.hpp"
#include "lbmshape/pipeline/morph_schedule.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"
#include "lbmshape/pipeline/stage_clock.hpp"
#include "lbmshape/sdf/grid_frame.hpp"

namespace lbmshape {

// Cells within this many voxels of the target's surface decide convergence:
// those whose values place the surface (marching cubes interpolates between
// the cells on either side of it).
inline constexpr float convergenceBand = 1.0f;

class MorphLattice {
public:
  virtual ~MorphLattice() = default;

  // Throws InputError naming the mesh when the source or the target
  // encloses nothing on the grid (before any output folder exists).
  virtual void requireEnclosedVolumes(const std::filesystem::path& source,
                                      const std::filesystem::path& target) const = 0;
  // How deep the target's inside reaches on the grid: its largest X (voxels).
  virtual double targetDepth() const = 0;
  // Before start(): max |X_source - X_target| over the cells within
  // convergenceBand of the target's surface, where the morph starts from.
  virtual double sourceErrorNearTarget() const = 0;
  // The target's zero level on the grid: where a morph that arrives ends.
  virtual TriangleMesh targetLevel() const = 0;
  // The solver, with the morph force S = Cs (X_target - X), started from the
  // source's field (and its noise, on the grid), for the steps of `schedule`.
  virtual void start(const ComputeDevice& device, const MorphOptions& options, const MorphSchedule& schedule,
                     StageClock& clock) = 0;
  // Before the steps from `step` on: sets the lattice up for them (the band
  // holds the bricks its moving surface is far from, morph_front.hpp), and
  // returns the first later step that needs it again.
  virtual int prepareSteps(int step) = 0;
  virtual SteppingSolver& solver() = 0;
  // gamma of the steps from now on (voxels^2 per step).
  virtual void setGamma(double gamma) = 0;
  // Cs of the morph force from now on (after start()).
  virtual void setMorphSpeed(double cs) = 0;
  // The field now, for a frame.
  virtual FrameField field() = 0;
  // The same, then one step (gamma set for it) under Cs `nextCs`: one pass
  // over the lattice where the solver can.
  virtual FrameField fieldThenStep(double nextCs) = 0;
  // After start(): from now on each frame's field is the pieces of its
  // surface, listed where the lattice runs, with the field's values at
  // `probes` (MorphFrameReport::probeCells()), instead of the field itself,
  // where the lattice can (the band's, on a device whose
  // ComputeDevice::surfacesOnTheDevice() says so). Returns whether it does.
  virtual bool framesAsSurfacePieces(std::vector<glm::ivec3> /*probes*/) { return false; }
  // max |X - X_target| over the cells within convergenceBand of the
  // target's surface (after start(), which keeps X_target there alone).
  virtual double errorNearTarget(const FrameField& field) const = 0;
  // After the last frame: lets the solver, the fields and the frames'
  // memory go before the animation is assembled. Nothing may be called
  // after.
  virtual void finish() = 0;
  // The target mesh's tree, where the distances built one (the band's),
  // else null: the last frame is compared with the target through it.
  virtual std::shared_ptr<const TriangleBvh> targetTree() const { return nullptr; }
  // Cells the lattice updates per step, and a description for the report.
  virtual size_t cells() const = 0;
  virtual nlohmann::json describe() const = 0;
};

// The narrow band with options.band (but not with options.noise, whose
// amplitude is a fraction of the field's largest value over the whole
// grid), else the grid. Computes both signed distance fields, as the "sdf"
// stage of `clock`; a band that would not fit `device` is refused as soon
// as its bricks are known; its width holds for `longest`, a schedule at least
// as long and diffusive as the one the morph will run. `beforeDistances` runs once the lattice is known
// to fit and before the distances: the morph's other checks go there, so
// that a job too large for the device says so first.
std::unique_ptr<MorphLattice> makeMorphLattice(const TriangleMesh& source, const TriangleMesh& target,
                                               const GridFrame& frame, const MorphOptions& options,
                                               const MorphSchedule& longest, const ComputeDevice& device,
                                               StageClock& clock, const std::function<void()>& beforeDistances);

}  // namespace lbmshape
