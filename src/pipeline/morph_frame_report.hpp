// The figures `morph --json` gives for each frame: where in the morph it is,
// how far its surface still is from the target, and its shape. The target
// is the target's own zero level on the morph's grid (what the morph can
// reach at that resolution), not the target mesh: a morph has arrived when
// the two coincide.
//
// A frame's distances cost a fraction of its extraction: from points on the
// frame to the target level through the target's tree, built once; from
// points on the target level to the frame by the frame's own field, |X| /
// |grad X| interpolated there (exact to first order: close to the frame,
// where X is nearly a distance, it is the distance). No tree is built on
// the writer's thread (see TriangleBvh).
#pragma once

#include <mutex>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/pipeline/frame_writer.hpp"
#include "lbmshape/sdf/grid_frame.hpp"

namespace lbmshape {

class MorphFrameReport {
public:
  // `targetLevel`: the target's zero level on `grid`. Without
  // `measureSurfaces` surface() must not be called, and nothing is prepared
  // for it.
  MorphFrameReport(TriangleMesh targetLevel, const GridFrame& grid, int frames, bool measureSurfaces);

  // From the lattice's side, once frame k's field is taken: its step, gamma
  // and Cs of the step that led to it, and the largest |X - X_target| near
  // the target, in voxels (converged below the tolerance).
  void lattice(int frame, int step, double gamma, double cs, double fieldError, bool converged);
  // From the frame writer's thread, once frame k's mesh is extracted from
  // its field: distances to the target level, volume and topology.
  // Thread-safe.
  void surface(int frame, const FrameField& field, const TriangleMesh& mesh);

  // One object per frame: {"frame", "step", "gamma", "cs", "max_field_error_voxels",
  // "converged", "mean_distance_to_target_voxels",
  // "max_distance_to_target_voxels", "volume", "components", "genus"}; the
  // last five null for a frame whose surface() was not measured.
  nlohmann::json toJson() const;

  // The cells whose values surface() reads from a frame's field, in
  // order of their grid index: what a frame listed as surface pieces on
  // the device carries as probes (SurfaceRequest::probes), so that its
  // figures are the same as from the whole field. Empty without
  // `measureSurfaces`.
  const std::vector<glm::ivec3>& probeCells() const { return probeCells_; }

  // A mesh (whose tree is `meshTree`) against the target level, densely
  // (every vertex too).
  SurfaceComparison compareWithTargetLevel(const TriangleMesh& mesh, const TriangleBvh& meshTree) const;

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
  std::vector<glm::dvec3> targetPoints_;       // on the target level, in grid coordinates
  std::vector<glm::ivec3> probeCells_;         // probeCells()
  GridFrame grid_;
  mutable std::mutex mutex_;
  std::vector<Frame> frames_;
};

}  // namespace lbmshape
