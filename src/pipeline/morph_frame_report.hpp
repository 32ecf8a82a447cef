// The figures `morph --json` gives for each frame: where in the morph it is,
// how far its surface still is from the target, and its shape. The target
// is the target's own zero level on the morph's grid (what the morph can
// reach at that resolution), not the target mesh: a morph has arrived when
// the two coincide.
#pragma once

#include <mutex>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/surface_comparison.hpp"
#include "mesh/triangle_mesh.hpp"

namespace lbmshape {

class MorphFrameReport {
public:
  // `targetLevel`: the target's zero level on the grid, `voxel` its cell size.
  MorphFrameReport(TriangleMesh targetLevel, double voxel, int frames);

  // From the lattice's side, once frame k's field is taken: its step, gamma
  // and Cs of the step that led to it, and the largest |X - X_target| near
  // the target, in voxels (converged below the tolerance).
  void lattice(int frame, int step, double gamma, double cs, double fieldError, bool converged);
  // From the frame writer's thread, once frame k's mesh is extracted:
  // distances to the target level, volume and topology. Thread-safe.
  void surface(int frame, const TriangleMesh& mesh);

  // One object per frame: {"frame", "step", "gamma", "cs", "max_field_error_voxels",
  // "converged", "mean_distance_to_target_voxels",
  // "max_distance_to_target_voxels", "volume", "components", "genus"}; the
  // last five null for a frame whose surface() was not measured.
  nlohmann::json toJson() const;

  // A mesh against the target level, densely (every vertex too).
  SurfaceComparison compareWithTargetLevel(const TriangleMesh& mesh) const;

private:
  struct Frame {
    int step = 0;
    double gamma = 0.0, cs = 0.0;
    double fieldError = 0.0;
    bool converged = false;
    std::optional<double> meanDistance, maxDistance;  // none for a frame with no surface
    bool measured = false;
    double volume = 0.0;
    size_t components = 0;
    std::optional<int64_t> genus;
  };

  TriangleMesh targetLevel_;
  std::optional<DistanceToSurface> toTarget_;  // none while the target level has no triangle
  double voxel_;
  mutable std::mutex mutex_;
  std::vector<Frame> frames_;
};

}  // namespace lbmshape
