#include "lbmshape/pipeline/morph_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>
#include <variant>

#include "lbmshape/core/worker_threads.hpp"
#include "lbmshape/lbm/band_width.hpp"
#include "lbmshape/pipeline/band_over_holes.hpp"
#include "lbmshape/pipeline/morph_front.hpp"
#include "lbmshape/pipeline/field_noise.hpp"
#include "lbmshape/pipeline/recycled_fields.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/sdf/band_signed_distance.hpp"
#include "lbmshape/sdf/enclosed_volume.hpp"
#include "lbmshape/sdf/hole_radius.hpp"
#include "lbmshape/sdf/signed_distance.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"
#include "lbmshape/surface/band_marching_cubes.hpp"
#include "lbmshape/surface/marching_cubes.hpp"

namespace lbmshape {
namespace {

// A morph's lattice runs under its source term (BandRunKind).
constexpr BandRunKind morphRun{.source = true};

// max |X - T| over the cells where |T| <= band (the same cells of one grid
// or one band).
double maxDifferenceNear(const std::vector<float>& X, const std::vector<float>& T, float band)
{
  double worst = 0.0;
#pragma omp parallel for reduction(max : worst) schedule(static)
  for (size_t i = 0; i < X.size(); ++i)
    if (std::abs(T[i]) <= band) worst = std::max(worst, double(std::abs(X[i] - T[i])));
  return worst;
}

// What a morph does alike on the grid and on the band: the two fields (a
// Volume or a BandField each), their checks, the target's own level, and the
// solver's controls.
template <class Field, class Solver>
class TwoFieldMorph : public MorphLattice {
public:
  void requireEnclosedVolumes(const std::filesystem::path& source, const std::filesystem::path& target) const override
  {
    requireEnclosedVolume(source_, source);
    requireEnclosedVolume(target_, target);
  }

  double targetDepth() const override { return deepestInside(target_); }
  double sourceErrorNearTarget() const override
  {
    return maxDifferenceNear(source_.values(), target_.values(), convergenceBand);
  }
  TriangleMesh targetLevel() const override { return extractSurface(target_, frame_); }

  SteppingSolver& solver() override { return *solver_; }
  void setGamma(double gamma) override { solver_->setUniformGamma(gamma); }
  void setMorphSpeed(double cs) override { solver_->setSourceStrength(float(cs), float(cs)); }
  FrameField field() override
  {
    std::shared_ptr<Field> out = frameFields_.take();
    solver_->fieldInto(*out);
    return readBack(std::shared_ptr<const Field>(std::move(out)));
  }
  FrameField fieldThenStep(double nextCs) override
  {
    std::shared_ptr<Field> out = frameFields_.take();
    solver_->fieldIntoThenStep(*out, SourceStrength{float(nextCs), float(nextCs)});
    return readBack(std::shared_ptr<const Field>(std::move(out)));
  }
  void finish() override
  {
    solver_.reset();
    source_ = Field();
    target_ = Field();
    frameFields_ = RecycledFields<Field>();  // frames still held return to the old shelf, which frees them
  }

  double errorNearTarget(const FrameField& field) const override
  {
    const std::vector<float>& X = std::get<std::shared_ptr<const Field>>(field)->values();
    double worst = 0.0;
#pragma omp parallel for reduction(max : worst) schedule(static)
    for (size_t k = 0; k < nearCells_.size(); ++k)
      worst = std::max(worst, double(std::abs(X[nearCells_[k]] - nearTarget_[k])));
    return worst;
  }

protected:
  explicit TwoFieldMorph(const GridFrame& frame) : frame_(frame) {}

  // A frame as it came from the solver, its bytes counted.
  FrameField readBack(FrameField frame)
  {
    readBackBytes_ += std::visit(
        [](const auto& f) -> double {
          if constexpr (std::is_same_v<std::decay_t<decltype(*f)>, SurfacePieces>)
            return double(f->crossings.size() * sizeof(SurfaceCrossing) + f->cubes.size() * sizeof(SurfaceCube) +
                          f->probeValues.size() * sizeof(float));
          else
            return double(f->values().size() * sizeof(float));
        },
        frame);
    ++framesReadBack_;
    return frame;
  }
  // The mean bytes a frame read back from the solver, for describe().
  double frameBytes() const { return framesReadBack_ ? readBackBytes_ / framesReadBack_ : 0.0; }

  // Once the solver holds the morph force: X_target where errorNearTarget()
  // reads it, and the rest let go (a field's worth of memory during the
  // morph: 44 MB on the band at 256^3).
  void keepOnlyNearTarget()
  {
    const std::vector<float>& T = target_.values();
    for (size_t i = 0; i < T.size(); ++i)
      if (std::abs(T[i]) <= convergenceBand) {
        nearCells_.push_back(i);
        nearTarget_.push_back(T[i]);
      }
    target_ = Field();
  }

  GridFrame frame_;
  Field source_, target_;
  std::unique_ptr<Solver> solver_;
  RecycledFields<Field> frameFields_;
  std::vector<size_t> nearCells_;  // keepOnlyNearTarget()
  std::vector<float> nearTarget_;
  double readBackBytes_ = 0.0;
  int framesReadBack_ = 0;
};

class GridMorph final : public TwoFieldMorph<Volume, LatticeSolver> {
public:
  GridMorph(const TriangleMesh& source, const TriangleMesh& target, const GridFrame& frame, StageClock& clock,
            const std::function<void()>& beforeDistances)
      : TwoFieldMorph(frame)
  {
    beforeDistances();
    source_ = clock.time("sdf", [&](Progress& p) { return signedDistance(source, frame, {.progress = &p}); });
    target_ = clock.time("sdf", [&](Progress& p) { return signedDistance(target, frame, {.progress = &p}); });
  }

  void start(const ComputeDevice& device, const MorphOptions& o, const MorphSchedule&, StageClock& clock) override
  {
    addFieldNoise(source_, o.noise);
    solver_ = clock.time("setup", [&] {
      device.checkFits(frame_.extent);
      auto s = device.makeSolver(frame_.extent);
      s->setUniformGamma(o.gamma);
      s->setSource(morphForce(o.cs));
      s->initialize(source_);
      return s;
    });
    source_ = Volume();  // no longer needed
    keepOnlyNearTarget();
  }

  int prepareSteps(int) override { return std::numeric_limits<int>::max(); }
  size_t cells() const override { return frame_.extent.cells(); }
  nlohmann::json describe() const override
  {
    return {{"kind", "grid"}, {"cells", cells()}, {"frame_read_back_bytes", frameBytes()}};
  }

private:
  // S = Cs X_target - Cs X: X_target uploaded once, Cs a push constant.
  LinearSource morphForce(double cs) const { return LinearSource{target_, float(cs), float(cs)}; }
};

// The narrow band of a morph holds the cells near the source's surface, near
// the target's, and every brick between the two (where the surface will
// pass: beyond them the two fields have the same sign). Cells stream where
// either field is within W of its surface or the two differ in sign; the
// rest are far from every place the surface goes through, and there the
// morph force alone moves X (X follows X_target + (X_source - X_target)
// e^(-Cs t), which the held cells do).
class BandMorph final : public TwoFieldMorph<BandField, BandSolver> {
public:
  BandMorph(const TriangleMesh& source, const TriangleMesh& target, const GridFrame& frame,
            const MorphSchedule& longest, const ComputeDevice& device, StageClock& clock,
            const std::function<void()>& beforeDistances)
      : TwoFieldMorph(frame)
  {
    halfWidth_ = streamingHalfWidth(longest.totalDiffusion() / longest.totalSteps(), longest.totalSteps());
    clock.time("sdf", [&](Progress& progress) {
      device.warmUpForTheBand(morphRun);  // the device opens while the distances are computed
      // Each mesh's hierarchy, built once for its bricks, the bricks between
      // and its distances (46 ms each time for the armadillo); the two
      // meshes' side by side.
      std::optional<TriangleBvh> sourceTreeMade;
      runSideBySide([&] { sourceTreeMade.emplace(source); },
                    [&] { targetTree_ = std::make_shared<const TriangleBvh>(target); });
      const TriangleBvh &sourceTree = *sourceTreeMade, &targetTree = *targetTree_;
      const auto bandBricks = [&](double halfWidth, bool overHoles) {
        std::shared_ptr<BrickSet> bricks, targetBricks;
        const double reach = halfWidth + 2.0;
        runSideBySide([&] { bricks = bricksNearSurface(source, sourceTree, frame, reach, overHoles); },
                      [&] { targetBricks = bricksNearSurface(target, targetTree, frame, reach, overHoles); });
        for (size_t s = 0; s < targetBricks->activeCount(); ++s) {
          const glm::ivec3 b = targetBricks->brick(int32_t(s));
          bricks->activate(b.x, b.y, b.z);
        }
        device.checkBandFits(*bricks, false, true);
        addBricksBetween(sourceTree, targetTree, frame, *bricks);
        device.checkBandFits(*bricks, false, true);
        return bricks;
      };
      const auto fieldsOn = [&](std::shared_ptr<BrickSet> bricks) {
        computeFields({source, sourceTree}, {target, targetTree}, std::move(bricks), progress,
                      [&device](const TriangleBvh& tree) { return device.bandDistances(tree); });
      };
      std::shared_ptr<BrickSet> bricks =
          withFansWhereTheyFit([&](bool overHoles) { return bandBricks(halfWidth_, overHoles); }, "the meshes'");
      beforeDistances();
      fieldsOn(bricks);
      // A mesh's hole wider than the band: the surface that closes it was
      // cut off, and the morph ended on a shape open there, or kept pieces
      // of the source's (sdf/hole_radius.hpp). Widened over the widest
      // hole, and again while it still leaves.
      const double wholeGrid = glm::length(glm::dvec3(frame.extent.nx, frame.extent.ny, frame.extent.nz));
      while ((surfaceLeavesTheBand(source_) || surfaceLeavesTheBand(target_)) && halfWidth_ < wholeGrid) {
        const double wider = std::max({halfWidthOverHoles(source, frame.voxel, halfWidth_),
                                       halfWidthOverHoles(target, frame.voxel, halfWidth_), 2.0 * halfWidth_});
        try {
          bricks = bandBricks(wider, true);
        } catch (const DeviceError& e) {
          // Refused before anything was allocated: the narrower band, with
          // what would close the holes.
          log::warning(
              "the frames are left open (or keep pieces of the source) where the surfaces that close the "
              "meshes' holes lie more than " +
              std::to_string(int(halfWidth_)) + " voxels from their triangles: a band " + std::to_string(int(wider)) +
              " voxels wide would hold them, but " + e.what());
          break;
        }
        halfWidth_ = wider;
        log::verbose("band widened to " + std::to_string(int(halfWidth_)) +
                     " voxels to hold the surfaces that close the meshes' holes");
        fieldsOn(bricks);
      }
    });
  }

  void start(const ComputeDevice& device, const MorphOptions& o, const MorphSchedule& schedule,
             StageClock& clock) override
  {
    piecesOnTheDevice_ = device.surfacesOnTheDevice();
    solver_ = clock.time("setup", [&] {
      auto s = device.makeBandSolver(source_.sharedBricks(), morphRun);
      s->setUniformGamma(o.gamma);
      s->setSource(morphForce(o.cs));
      std::vector<uint8_t> flags = streams();
      front_.emplace(source_, target_, flags, halfWidth_ + frontMargin, schedule);
      held_ = front_->heldDuring(0);
      s->setHeldBricks(held_);
      s->initialize(std::move(source_), std::move(flags));  // the solver keeps it until its first step
      return s;
    });
    bricks_ = target_.sharedBricks();
    keepOnlyNearTarget();
  }

  int prepareSteps(int step) override
  {
    std::vector<uint8_t> held = front_->heldDuring(step);
    if (held != held_) solver_->setHeldBricks(held_ = std::move(held));
    return front_->sameUntil(step);
  }

  bool framesAsSurfacePieces(std::vector<glm::ivec3> probes) override
  {
    if (!piecesOnTheDevice_) return false;
    pieces_ = SurfaceRequest{.isovalue = 0.0f, .nearBand = convergenceBand, .probes = std::move(probes)};
    return true;
  }
  FrameField field() override
  {
    if (!pieces_) return TwoFieldMorph::field();
    return readBack(std::make_shared<const SurfacePieces>(solver_->surfacePieces(*pieces_)));
  }
  FrameField fieldThenStep(double nextCs) override
  {
    if (!pieces_) return TwoFieldMorph::fieldThenStep(nextCs);
    return readBack(std::make_shared<const SurfacePieces>(
        solver_->surfacePiecesThenStep(*pieces_, SourceStrength{float(nextCs), float(nextCs)})));
  }
  double errorNearTarget(const FrameField& field) const override
  {
    if (const auto* pieces = std::get_if<std::shared_ptr<const SurfacePieces>>(&field))
      return (*pieces)->errorNearBase.value();
    return TwoFieldMorph::errorNearTarget(field);
  }

  std::shared_ptr<const TriangleBvh> targetTree() const override { return targetTree_; }
  size_t cells() const override { return bricks_->storedCells(); }
  nlohmann::json describe() const override
  {
    const BrickSet& bricks = *bricks_;
    return {{"kind", "band"},
            {"half_width", halfWidth_},
            {"bricks", bricks.activeCount()},
            {"cells", bricks.storedCells()},
            {"fraction_of_grid", double(bricks.storedCells()) / double(frame_.extent.cells())},
            {"streaming_fraction", front_ ? nlohmann::json(front_->meanStreamingFraction()) : nlohmann::json(nullptr)},
            {"frozen_fraction", front_ ? nlohmann::json(front_->meanFrozenFraction()) : nlohmann::json(nullptr)},
            {"frame_read_back_bytes", frameBytes()}};
  }

private:
  // How far beyond the streaming half-width a brick's predicted X counts
  // as near the surface: diffusion moves the surface from the prediction
  // by about gamma t times its curvature, a voxel or two over a morph.
  static constexpr double frontMargin = 2.0;

  // S = Cs X_target - Cs X.
  BandSource morphForce(double cs) const { return BandSource{target_, float(cs), float(cs)}; }

  // The bricks between the two surfaces: outside both bands, and on
  // different sides of the two. No surface comes within W + 2 voxels of an
  // inactive brick, so a face-connected region of them is on one side of
  // each mesh (as markFarSides assumes too): one winding number of each mesh
  // at one brick of the region decides it all.
  static void addBricksBetween(const TriangleBvh& sourceTree, const TriangleBvh& targetTree, const GridFrame& frame,
                               BrickSet& bricks)
  {
    const Extent3 grid = bricks.bricks();
    std::vector<uint8_t> seen(grid.cells(), 0), between(grid.cells(), 0);
    std::vector<glm::ivec3> region;
    const glm::ivec3 steps[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int z = 0; z < grid.nz; ++z)
      for (int y = 0; y < grid.ny; ++y)
        for (int x = 0; x < grid.nx; ++x) {
          if (seen[grid.index(x, y, z)] || bricks.slot(x, y, z) != noBrick) continue;
          const glm::dvec3 centre = frame.toWorld(glm::dvec3(brickEdge * glm::ivec3(x, y, z)) + 0.5 * (brickEdge - 1));
          const uint8_t differ = (sourceTree.windingNumber(centre) > 0.5) != (targetTree.windingNumber(centre) > 0.5);
          region.assign(1, glm::ivec3(x, y, z));
          seen[grid.index(x, y, z)] = 1;
          for (size_t k = 0; k < region.size(); ++k) {
            const glm::ivec3 b = region[k];
            between[grid.index(b.x, b.y, b.z)] = differ;
            for (const glm::ivec3& d : steps) {
              const glm::ivec3 n = b + d;
              if (!grid.contains(n.x, n.y, n.z) || seen[grid.index(n.x, n.y, n.z)] ||
                  bricks.slot(n.x, n.y, n.z) != noBrick)
                continue;
              seen[grid.index(n.x, n.y, n.z)] = 1;
              region.push_back(n);
            }
          }
        }
    for (size_t b = 0; b < grid.cells(); ++b)
      if (between[b]) bricks.activate(int(b % grid.nx), int(b / grid.nx % grid.ny), int(b / grid.nx / grid.ny));
  }

  struct MeshWithTree {
    const TriangleMesh& mesh;
    const TriangleBvh& tree;
  };

  void computeFields(const MeshWithTree& source, const MeshWithTree& target, std::shared_ptr<const BrickSet> bricks,
                     Progress& progress, const std::function<UnsignedBandDistances(const TriangleBvh&)>& distancesFrom)
  {
    // The cells between the two surfaces need their true distances: the
    // force moves each from one to the other at its own pace.
    // The two side by side, each on one thread (the progress is the
    // source's).
    const BandDistanceOptions options{
        .halfWidth = halfWidth_, .clampBeyondHalfWidth = false, .progress = &progress, .distancesFrom = distancesFrom};
    BandDistanceOptions quiet = options;
    quiet.progress = nullptr;
    runSideBySide([&] { source_ = signedDistanceOn(source.mesh, source.tree, frame_, bricks, options); },
                  [&] { target_ = signedDistanceOn(target.mesh, target.tree, frame_, bricks, quiet); });
  }

  std::vector<uint8_t> streams() const
  {
    const std::vector<float>& A = source_.values();
    const std::vector<float>& T = target_.values();
    std::vector<uint8_t> flags(A.size());
    const float w = float(halfWidth_);
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < A.size(); ++i)
      flags[i] = std::abs(A[i]) < w || std::abs(T[i]) < w || (A[i] > 0) != (T[i] > 0);
    return flags;
  }

  double halfWidth_ = 0.0;
  std::shared_ptr<const TriangleBvh> targetTree_;
  bool piecesOnTheDevice_ = false;          // start(): ComputeDevice::surfacesOnTheDevice()
  std::optional<SurfaceRequest> pieces_;    // framesAsSurfacePieces(): what each frame lists
  std::shared_ptr<const BrickSet> bricks_;  // the band's, kept past the fields
  std::optional<MorphFront> front_;
  std::vector<uint8_t> held_;  // the held bricks set on the solver
};

}  // namespace

std::unique_ptr<MorphLattice> makeMorphLattice(const TriangleMesh& source, const TriangleMesh& target,
                                               const GridFrame& frame, const MorphOptions& options,
                                               const MorphSchedule& longest, const ComputeDevice& device,
                                               StageClock& clock, const std::function<void()>& beforeDistances)
{
  if (!options.band || options.noise.amplitude > 0.0) {
    device.warnThatTheGridsDistancesAreTheCpus();
    device.warnThatTheGridsFramesAreTheCpus();
    return std::make_unique<GridMorph>(source, target, frame, clock, beforeDistances);
  }
  device.surfacesOnTheDevice();  // --extract device on the reference: a usage error before any work
  return std::make_unique<BandMorph>(source, target, frame, longest, device, clock, beforeDistances);
}

}  // namespace lbmshape
