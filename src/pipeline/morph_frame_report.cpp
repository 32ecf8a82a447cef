#include "lbmshape/pipeline/morph_frame_report.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/analysis/surface_sampling.hpp"
#include "lbmshape/surface/field_sampling.hpp"

namespace lbmshape {
namespace {

// Random points on each surface for a frame's distances: enough for the
// mean within about a hundredth of a voxel. The maximum, taken over the same
// points, can fall short of the Hausdorff distance by their spacing; `final`
// in the morph's report measures the last frame more densely.
constexpr size_t samplesPerFrame = 4000;

nlohmann::json orNull(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

// From points of the target level to the frame's zero level, in voxels, by
// the frame's field: |X| / |grad X|, the gradient's length kept from
// vanishing where two fronts meet (a blend's gradient can cancel).
template <class Field>
DirectedDistance distanceByField(const Field& field, const std::vector<glm::dvec3>& points)
{
  DirectedDistance d;
  double sum = 0.0, sum2 = 0.0;
  for (const glm::dvec3& p : points) {
    const auto [value, gradient] = sampleWithGradient(field, p);
    const double distance = std::abs(value) / std::max(glm::length(gradient), 0.5);
    sum += distance, sum2 += distance * distance;
    d.max = std::max(d.max, distance);
  }
  d.samples = points.size();
  if (!points.empty()) d.mean = sum / double(points.size()), d.rms = std::sqrt(sum2 / double(points.size()));
  return d;
}

// The order of a frame's probes: by the cells' index in the grid.
auto byGridIndex(const Extent3& extent)
{
  return [&extent](const glm::ivec3& a, const glm::ivec3& b) {
    return extent.index(a.x, a.y, a.z) < extent.index(b.x, b.y, b.z);
  };
}

// A field read through a frame's probes (the cells distanceByField reads,
// in byGridIndex order, and their values).
class ProbedField {
public:
  ProbedField(const Extent3& extent, const std::vector<glm::ivec3>& cells, const std::vector<float>& values)
      : extent_(extent), cells_(cells), values_(values)
  {
    if (values.size() != cells.size()) throw std::logic_error("a frame's probes without their values");
  }
  const Extent3& extent() const { return extent_; }
  float at(int x, int y, int z) const
  {
    const auto found = std::lower_bound(cells_.begin(), cells_.end(), glm::ivec3(x, y, z), byGridIndex(extent_));
    if (found == cells_.end() || *found != glm::ivec3(x, y, z)) throw std::logic_error("a cell that was not probed");
    return values_[size_t(found - cells_.begin())];
  }

private:
  Extent3 extent_;
  const std::vector<glm::ivec3>& cells_;
  const std::vector<float>& values_;
};

// Records the cells distanceByField reads: its probes.
struct CellRecorder {
  const Extent3& extent() const { return grid; }
  float at(int x, int y, int z) const
  {
    cells.emplace_back(x, y, z);
    return 0.0f;
  }
  Extent3 grid;
  mutable std::vector<glm::ivec3> cells;
};

}  // namespace

MorphFrameReport::MorphFrameReport(TriangleMesh targetLevel, const GridFrame& grid, int frames, bool measureSurfaces)
    : targetLevel_(std::move(targetLevel)), grid_(grid), frames_(size_t(frames))
{
  if (!measureSurfaces || targetLevel_.triangles.empty()) return;
  toTarget_.emplace(targetLevel_);
  for (const SurfaceSample& s : sampleSurface(targetLevel_, samplesPerFrame, 1))
    targetPoints_.push_back(grid_.toGrid(s.point));
  CellRecorder recorder{grid_.extent, {}};
  distanceByField(recorder, targetPoints_);
  probeCells_ = std::move(recorder.cells);
  std::sort(probeCells_.begin(), probeCells_.end(), byGridIndex(grid_.extent));
  probeCells_.erase(std::unique(probeCells_.begin(), probeCells_.end()), probeCells_.end());
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

void MorphFrameReport::surface(int frame, const FrameField& field, const TriangleMesh& mesh)
{
  Frame measured;
  const MeshTopology topology = analyzeTopology(mesh);
  measured.volume = topology.signedVolume;
  measured.components = topology.components;
  measured.genus = topology.genus;
  if (topology.area > 0.0 && toTarget_) {
    const DirectedDistance there =
        toTarget_->from(mesh, ComparisonOptions{samplesPerFrame, 0.0, false, uint64_t(frame) + 1});
    const DirectedDistance back = std::visit(
        [&](const auto& f) {
          if constexpr (std::is_same_v<std::decay_t<decltype(*f)>, SurfacePieces>)
            return distanceByField(ProbedField(grid_.extent, probeCells_, f->probeValues), targetPoints_);
          else
            return distanceByField(*f, targetPoints_);
        },
        field);
    measured.meanDistance = 0.5 * (there.mean / grid_.voxel + back.mean);
    measured.maxDistance = std::max(there.max / grid_.voxel, back.max);
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

SurfaceComparison MorphFrameReport::compareWithTargetLevel(const TriangleMesh& mesh, const TriangleBvh& meshTree) const
{
  const TriangleBvh levelTree(targetLevel_, TriangleBvh::Queries::ClosestOnly);
  return compareSurfaces(mesh, meshTree, targetLevel_, levelTree, ComparisonOptions{20000, 0.0, true});
}

nlohmann::json MorphFrameReport::toJson() const
{
  std::lock_guard lock(mutex_);
  nlohmann::json frames = nlohmann::json::array();
  for (size_t k = 0; k < frames_.size(); ++k) {
    const Frame& f = frames_[k];
    frames.push_back({{"frame", k},
                      {"step", f.step},
                      // Of the step that led to the frame: none leads to a frame at step 0.
                      {"gamma", f.step > 0 ? nlohmann::json(f.gamma) : nlohmann::json(nullptr)},
                      {"cs", f.step > 0 ? nlohmann::json(f.cs) : nlohmann::json(nullptr)},
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
