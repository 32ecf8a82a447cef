#include "pipeline/morph_frame_report.hpp"

#include <algorithm>

#include "analysis/mesh_topology.hpp"

namespace lbmshape {
namespace {

// Random points on each surface for a frame's distances: enough for the
// mean within about a hundredth of a voxel, few enough that the frame's
// tree, not the points, is most of the cost. The maximum, taken over the same
// points, can fall short of the Hausdorff distance by their spacing; `final`
// in the morph's report measures the last frame more densely.
constexpr size_t samplesPerFrame = 4000;

nlohmann::json orNull(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

}  // namespace

MorphFrameReport::MorphFrameReport(TriangleMesh targetLevel, double voxel, int frames)
    : targetLevel_(std::move(targetLevel)), voxel_(voxel), frames_(size_t(frames))
{
  if (!targetLevel_.triangles.empty()) toTarget_.emplace(targetLevel_);
}

void MorphFrameReport::lattice(int frame, int step, double gamma, double cs, double fieldError, bool converged)
{
  std::lock_guard lock(mutex_);
  Frame& f = frames_.at(size_t(frame));
  f.step = step;
  f.gamma = gamma;
  f.cs = cs;
  f.fieldError = fieldError;
  f.converged = converged;
}

void MorphFrameReport::surface(int frame, const TriangleMesh& mesh)
{
  Frame measured;
  const MeshTopology topology = analyzeTopology(mesh);
  measured.volume = topology.signedVolume;
  measured.components = topology.components;
  measured.genus = topology.genus;
  if (topology.area > 0.0 && toTarget_) {
    // Both ways, as compareSurfaces does, but only the frame's tree is new.
    const ComparisonOptions options{samplesPerFrame, 0.0, false, uint64_t(frame) + 1};
    const DirectedDistance there = toTarget_->from(mesh, options);
    const DirectedDistance back = DistanceToSurface(mesh, TriangleBvh::Build::OnThisThread).from(targetLevel_, options);
    measured.meanDistance = 0.5 * (there.mean + back.mean) / voxel_;
    measured.maxDistance = std::max(there.max, back.max) / voxel_;
  }
  std::lock_guard lock(mutex_);
  Frame& f = frames_.at(size_t(frame));
  f.meanDistance = measured.meanDistance;
  f.maxDistance = measured.maxDistance;
  f.measured = true;
  f.volume = measured.volume;
  f.components = measured.components;
  f.genus = measured.genus;
}

SurfaceComparison MorphFrameReport::compareWithTargetLevel(const TriangleMesh& mesh) const
{
  return compareSurfaces(mesh, targetLevel_, ComparisonOptions{20000, 0.0, true});
}

nlohmann::json MorphFrameReport::toJson() const
{
  std::lock_guard lock(mutex_);
  nlohmann::json frames = nlohmann::json::array();
  for (size_t k = 0; k < frames_.size(); ++k) {
    const Frame& f = frames_[k];
    frames.push_back({{"frame", k},
                      {"step", f.step},
                      {"gamma", f.gamma},
                      {"cs", f.cs},
                      {"max_field_error_voxels", f.fieldError},
                      {"converged", f.converged},
                      {"mean_distance_to_target_voxels", orNull(f.meanDistance)},
                      {"max_distance_to_target_voxels", orNull(f.maxDistance)},
                      {"volume", f.measured ? nlohmann::json(f.volume) : nlohmann::json(nullptr)},
                      {"components", f.measured ? nlohmann::json(f.components) : nlohmann::json(nullptr)},
                      {"genus", f.genus ? nlohmann::json(*f.genus) : nlohmann::json(nullptr)}});
  }
  return frames;
}

}  // namespace lbmshape
