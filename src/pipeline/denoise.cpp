#include "lbmshape/pipeline/denoise.hpp"

#include <optional>
#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/analysis/normal_noise.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/host_memory.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/number_text.hpp"
#include "lbmshape/core/parameter_bounds.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/lbm/relaxation.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_validation.hpp"
#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/mesh/mesh_writer.hpp"
#include "lbmshape/pipeline/band_over_holes.hpp"
#include "lbmshape/pipeline/feature_probe.hpp"
#include "lbmshape/pipeline/input_orientation.hpp"
#include "lbmshape/pipeline/parts_check.hpp"
#include "lbmshape/pipeline/interruptible_steps.hpp"
#include "lbmshape/pipeline/render_job.hpp"
#include "lbmshape/pipeline/smoothing_radius.hpp"
#include "lbmshape/pipeline/smoothing_stop.hpp"
#include "lbmshape/pipeline/twicing.hpp"
#include "lbmshape/render/curvature_colours.hpp"
#include "lbmshape/render/png_file.hpp"
#include "lbmshape/pipeline/stage_clock.hpp"
#include "lbmshape/lbm/band_width.hpp"
#include "lbmshape/sdf/band_signed_distance.hpp"
#include "lbmshape/sdf/hole_radius.hpp"
#include "lbmshape/sdf/enclosed_volume.hpp"
#include "lbmshape/sdf/signed_distance.hpp"
#include "lbmshape/surface/band_marching_cubes.hpp"
#include "lbmshape/surface/marching_cubes.hpp"
#include "lbmshape/surface/volume_keeping.hpp"

namespace lbmshape {
namespace {

// --preserve-features finds the edges on a copy of the field smoothed
// (feature_probe.hpp), and halves gamma where the mean curvature there is
// 0.2 per voxel (a radius of 5 voxels). Chosen on the fandisk with vertex
// noise of 0.2 and 0.3 mean edge lengths (docs/denoising.md has the
// measurements).
constexpr double featureEdgeCurvature = 0.2;

const char* smoothingName(Smoothing s)
{
  switch (s) {
  case Smoothing::Isotropic: return "isotropic";
  case Smoothing::Anisotropic: return "anisotropic";
  case Smoothing::PreserveFeatures: return "preserve-features";
  }
  return "?";
}

nlohmann::json meshSummary(const TriangleMesh& mesh, const MeshTopology& t)
{
  return {{"vertices", mesh.vertexCount()},
          {"triangles", mesh.triangleCount()},
          {"components", t.components},
          {"closed_manifold", t.closedManifold},
          {"genus", t.genus ? nlohmann::json(*t.genus) : nlohmann::json(nullptr)},
          {"boundary_edges", t.boundaryEdges},
          {"area", t.area},
          {"volume", t.signedVolume}};
}

// What an interrupted denoise has done: the lattice steps, and nothing written.
std::function<std::string()> stepsDone(const SteppingSolver& solver)
{
  return [&solver] { return "after " + std::to_string(solver.stepsTaken()) + " steps; nothing was written"; };
}

// Runs `count` more steps as a part of the stage's progress, in batches
// between which Ctrl-C is honoured; the field does not depend on the batches.
void stepShowingProgress(SteppingSolver& solver, int count, Progress& progress, const char* part = "steps",
                         double share = 1.0)
{
  progress.beginPart(part, count, share);
  InterruptibleSteps(solver).advanceTo(solver.stepsTaken() + count, stepsDone(solver), &progress);
}

// The two kinds of lattice differ in how they start; the smoothing is
// written once for both. The band's solver takes `field` over, so that the
// band is not held twice while it runs (at --res 512, 47 MB); the grid's
// caller keeps it, for --steps auto (GridReading) and for a restart.
//
// A start with a restart to come (the edge-finding copy first): the band's
// solver holds the field for it.
void startToRestart(LatticeSolver& solver, const Volume& field, double) { solver.initialize(field); }
void startToRestart(BandSolver& solver, BandField& field, double halfWidth)
{
  solver.holdFieldForRestart();
  solver.initialize(std::move(field), halfWidth);
}
void restart(LatticeSolver& solver, const Volume& field, double) { solver.initialize(field); }
void restart(BandSolver& solver, const BandField&, double) { solver.restart(); }
// The only start of a smoothing.
void startForGood(LatticeSolver& solver, Volume& field, double) { solver.initialize(field); }
void startForGood(BandSolver& solver, BandField& field, double halfWidth)
{
  solver.initialize(std::move(field), halfWidth);
}

// A smoothed field, the steps that made it, and every step the lattice ran
// (with --steps auto one or two more, to see the speed level off, and with
// --preserve-features the edge-finding copy's): what MLUPS count.
template <class Field>
struct SmoothedField {
  Field field;
  int steps = 0;
  int stepsRun = 0;
  std::vector<double> speeds;  // --steps auto's readings, voxels a step (smoothing_stop.hpp)
  // Twiced: the weight of what the second smoothing took, given back (twicing.hpp).
  std::optional<float> twicingWeight;
};

// What --steps auto reads from each kind of lattice. The grid computes the
// field of the step it has reached (a pass over the lattice), reads it back
// and compares it with the last on the host; its other copy still holds the
// step before. The band reads one step late and with no pass: after step k
// its two copies of the moments hold the fields of steps k - 1 and k - 2
// (BandSolver::storedField), which it compares where they are
// (BandSolver::surfaceSpeed): only the field it keeps is read back.
class GridReading {
public:
  static constexpr int lag = 0;
  GridReading(LatticeSolver& solver, const Volume& x0) : solver_(solver), speed_(x0.values()) {}
  double speedOfTheStep()
  {
    last_ = solver_.field();
    return speed_.advance(last_.values());
  }
  Volume fieldOfTheStep() { return std::move(last_); }
  Volume fieldBeforeIt() { return solver_.previousField(); }

private:
  LatticeSolver& solver_;
  smoothing_stop::SurfaceSpeed speed_;
  Volume last_;
};

class BandReading {
public:
  static constexpr int lag = 1;
  BandReading(BandSolver& solver, const BandField&) : solver_(solver) {}
  double speedOfTheStep() { return solver_.surfaceSpeed(); }
  BandField fieldOfTheStep() { return solver_.storedField(1); }
  BandField fieldBeforeIt() { return solver_.storedField(2); }

private:
  BandSolver& solver_;
};

GridReading readingOf(LatticeSolver& solver, const Volume& x0) { return {solver, x0}; }
BandReading readingOf(BandSolver& solver, const BandField& x0) { return {solver, x0}; }

// --steps auto: runs the lattice until the surface's speed after a step
// has levelled off and returns that step (mostSteps + 1 if none did by
// mostSteps); the lattice is then `reading.lag` steps past it. The speeds
// read go to `speeds`, one a step.
template <class Solver, class Reading>
int runUntilTheSpeedLevelsOff(Solver& solver, Reading& reading, Progress& progress, std::vector<double>& speeds)
{
  using namespace smoothing_stop;
  InterruptibleSteps stepper(solver);
  double previous = 0.0;
  for (int n = 1; n <= mostSteps; ++n) {
    stepper.advanceTo(n + reading.lag, stepsDone(solver), &progress);
    const double now = reading.speedOfTheStep();
    speeds.push_back(now);
    if (levelledOff(n, previous, now)) return n;
    previous = now;
  }
  return mostSteps + 1;
}

// The smoothing S of `steps` steps twiced (twicing.hpp) with `weight`, the
// lattice at or before step `steps`: S X at step `steps`, S^2 X at twice
// as many.
template <class Solver, class Field>
SmoothedField<Field> twiceTheSmoothing(Solver& solver, int steps, Progress& progress, float weight = 1.0f)
{
  InterruptibleSteps stepper(solver);
  stepper.advanceTo(steps, stepsDone(solver), &progress);
  Field once = solver.field();
  stepper.advanceTo(2 * steps, stepsDone(solver), &progress);
  twice(once.values(), solver.field().values(), weight);
  return {std::move(once), steps, 2 * steps, {}, weight};
}

// When --steps auto twices the smoothing: never (--no-twicing, and the
// smoothings other than the default), always (--twicing), or where the
// noise needs twicingFromSteps plain steps or more (twicing.hpp).
enum class Twice { Never, Always, WherePays };

// --steps auto: plain, the field one step before the speed levelled off,
// which the lattice still holds (or that of mostSteps), or of
// `fewestForNoise` steps where the noise's amplitude asks for more
// (smoothing_stop.hpp; never twiced: twicing would give back the slow
// noise); twiced, S of twicedSteps(n) steps, n the step at which plain
// smoothing's speed levelled off (twice the steps it keeps).
template <class Solver, class Field>
SmoothedField<Field> stepsTheNoiseNeeds(Solver& solver, Field x0, Progress& progress, Twice when, int fewestForNoise)
{
  auto reading = readingOf(solver, x0);
  x0 = Field();
  std::vector<double> speeds;
  const int levelled = runUntilTheSpeedLevelsOff(solver, reading, progress, speeds);
  const int kept = std::min(levelled - 1, smoothing_stop::mostSteps);
  const bool noiseAsksForMore = kept < fewestForNoise;
  if (when == Twice::Always || (when == Twice::WherePays && kept >= twicingFromSteps && !noiseAsksForMore)) {
    const bool always = when == Twice::Always;
    SmoothedField<Field> twiced = twiceTheSmoothing<Solver, Field>(solver, twicedSteps(levelled), progress,
                                                                   always ? 1.0f : automaticTwicingWeight);
    twiced.speeds = std::move(speeds);
    return twiced;
  }
  const int stepsRun = std::min(levelled, smoothing_stop::mostSteps) + reading.lag;
  if (noiseAsksForMore) {
    // The lattice is at step levelled + lag (at most fewestForNoise + 1),
    // the field of step `levelled` the reading's own.
    if (fewestForNoise == levelled)
      return {reading.fieldOfTheStep(), levelled, stepsRun, std::move(speeds), std::nullopt};
    InterruptibleSteps(solver).advanceTo(fewestForNoise, stepsDone(solver), &progress);
    return {solver.field(), fewestForNoise, fewestForNoise, std::move(speeds), std::nullopt};
  }
  if (levelled > smoothing_stop::mostSteps)
    return {reading.fieldOfTheStep(), smoothing_stop::mostSteps, stepsRun, std::move(speeds), std::nullopt};
  return {reading.fieldBeforeIt(), levelled - 1, stepsRun, std::move(speeds), std::nullopt};
}

// Whether the smoothing is twiced whatever the noise (--twicing), and
// whether it may be: told, or unset with the default smoothing's steps
// chosen by the noise (Twice::WherePays).
bool twicedAlways(const DenoiseOptions& o) { return o.twicing.value_or(false); }
bool mayBeTwiced(const DenoiseOptions& o)
{
  return o.twicing.value_or(!o.steps && o.smoothing == Smoothing::PreserveFeatures);
}

// The most steps of the smoothing S (twiced, the lattice runs twice as
// many), not counting the edge-finding copy's; `twiced`: if it may be.
int mostSmootherSteps(const DenoiseOptions& o, bool twiced)
{
  return o.steps.value_or(twiced ? twicedSteps(smoothing_stop::mostSteps + 1) : smoothing_stop::mostSteps);
}
int mostSmoothingSteps(const DenoiseOptions& o)
{
  const bool twiced = mayBeTwiced(o);
  return (twiced ? 2 : 1) * mostSmootherSteps(o, twiced);
}

// The steps of one start of `solver` from `x0`: --steps of them, or as many
// as the noise needs (smoothing_stop.hpp); twiced with --twicing or where
// it pays. `x0` is let go once it is not needed.
template <class Solver, class Field>
SmoothedField<Field> runSteps(Solver& solver, Field x0, const DenoiseOptions& o, int fewestForNoise, Progress& progress,
                              const char* part = "steps", double share = 1.0)
{
  progress.beginPart(part, mostSmoothingSteps(o), share);
  if (o.steps) {
    x0 = Field();
    if (twicedAlways(o)) return twiceTheSmoothing<Solver, Field>(solver, *o.steps, progress);
    InterruptibleSteps(solver).advanceTo(*o.steps, stepsDone(solver), &progress);
    return {solver.field(), *o.steps, *o.steps, {}, std::nullopt};
  }
  const Twice when = twicedAlways(o) ? Twice::Always : mayBeTwiced(o) ? Twice::WherePays : Twice::Never;
  SmoothedField<Field> smoothed = stepsTheNoiseNeeds(solver, std::move(x0), progress, when, fewestForNoise);
  log::verbose("the noise is gone after " + std::to_string(smoothed.steps) + " steps" +
               (smoothed.twicingWeight ? ", twiced" : ""));
  return smoothed;
}

// Whether the smoothing first finds the edges on a copy (feature_probe.hpp):
// --preserve-features, unless there are no steps (conversion alone).
bool findsEdges(const DenoiseOptions& o) { return o.smoothing == Smoothing::PreserveFeatures && o.steps != 0; }

// Runs the smoothing on `solver`, starting from `field`; a band solver
// streams the cells within `halfWidth` of the surface. `field` is let go
// once the solver has taken it, so that its memory is free while the
// lattice runs.
template <class Solver, class Field>
SmoothedField<Field> smooth(Solver& solver, Field field, const DenoiseOptions& o, int fewestForNoise, double halfWidth,
                            Progress& progress)
{
  if (!findsEdges(o)) {
    // The paper's rule (Eq. 20) runs inside the solver, on the device:
    // nothing leaves it between steps.
    if (o.smoothing == Smoothing::Anisotropic)
      solver.setPaperRule(o.gamma);
    else
      solver.setUniformGamma(o.gamma);
    startForGood(solver, field, halfWidth);
    return runSteps(solver, std::move(field), o, fewestForNoise, progress);
  }
  const FeatureProbe probe = featureProbe();
  const int steps = mostSmoothingSteps(o);
  const double probeShare = double(probe.steps) / (probe.steps + steps);
  solver.setUniformGamma(probe.gamma);
  startToRestart(solver, field, halfWidth);
  returnFreedHeapMemory();  // the start's streaming flags and rows, before the rule's peak
  stepShowingProgress(solver, probe.steps, progress, "finding the edges", probeShare);
  solver.setFeaturePreservingGamma(o.gamma, featureEdgeCurvature);  // on the device, for a Vulkan solver
  restart(solver, field, halfWidth);
  SmoothedField<Field> smoothed =
      runSteps(solver, std::move(field), o, fewestForNoise, progress, "steps", 1.0 - probeShare);
  smoothed.stepsRun += probe.steps;
  return smoothed;
}

// How far from the surface the band streams: as far as the smoothing's
// steps need, or the edge-finding copy's, whichever is farther.
double bandHalfWidth(const DenoiseOptions& o)
{
  // Twiced, the band is the one S's own steps need, not S^2's: measured,
  // results on bands from that width to S^2's lie within 1e-5 voxel of
  // each other (docs/denoising.md, "Twicing"). It is chosen before the
  // steps are known, so where the smoothing may be twiced it is the one
  // the most steps S may take need (8 voxels at the default gamma, 7 for
  // plain smoothing: about 7 % more cells).
  const double smoothing = streamingHalfWidth(o.gamma, mostSmootherSteps(o, mayBeTwiced(o)));
  if (!findsEdges(o)) return smoothing;
  const FeatureProbe probe = featureProbe();
  return std::max(smoothing, streamingHalfWidth(probe.gamma, probe.steps));
}

// The lattice stages of a denoise: signed distance, smoothing, surface.
struct Smoothed {
  TriangleMesh mesh;
  nlohmann::json lattice;              // what the lattice held: cells, bytes
  size_t cells = 0;                    // cells updated per step
  int steps = 0;                       // the steps whose field was kept (the last start's)
  int stepsRun = 0;                    // the steps the lattice ran for it
  double volumeShift = 0;              // voxels the field was shifted by to keep the volume
  bool distancesOnDevice = false;      // where the signed distance's distances were computed (--sdf)
  std::vector<double> speeds;          // --steps auto's readings (SmoothedField)
  std::optional<float> twicingWeight;  // twiced, with this weight (SmoothedField)
  double inputFieldVoxels = 0;         // cells inside the input's field, with the volume kept (else 0)
};

// The largest level-set shift that keeping the volume may apply, in voxels:
// the shrinking of a denoise at its defaults is a few tenths of a voxel, and
// a shift must stay well inside the narrow band (at least 3 voxels wide).
constexpr double maxVolumeShift = 2.0;

// Shifts the smoothed field so that it encloses `enclosed` voxels, as the
// input's field did; returns the shift.
template <class Field>
double keepVolume(Field& smoothed, double enclosed)
{
  const double shift = volumeKeepingShift(smoothed, enclosed, maxVolumeShift);
  shiftField(smoothed, shift);
  log::verbose("volume kept by a level-set shift of " + std::to_string(shift) + " voxels");
  return shift;
}

// The most by which the input mesh's volume and its zero level's may differ
// for meshVolumeShift() to take it for the triangles' bias: 3.6 % was the
// most measured (the Horse at --res 48).
constexpr double mostTriangleBias = 0.1;
// Nearer the input's volume than this (relative) a surface is not made again.
constexpr double volumeCloseEnough = 1e-4;

// What is done to the triangles of a zero level once they are made
// (relaxation), before their volume is measured.
using SurfaceFinish = std::function<void(TriangleMesh&)>;

// The smoothed field's surface: marching cubes, then `finish`. Where the
// input mesh's volume is known (`meshVolume`: a closed input, volume kept),
// the field is shifted once more so that the finished triangles enclose
// that volume and not only the field's cells (volumePerShift,
// meshVolumeShift), and the surface made again; the shift is added to
// `shift`, within maxVolumeShift.
template <class Field>
TriangleMesh surfaceKeepingTheVolume(Field& field, const GridFrame& frame, std::optional<double> meshVolume,
                                     double& shift, const SurfaceFinish& finish, StageClock& clock)
{
  const auto surface = [&] {
    TriangleMesh mesh = clock.time("extract", [&] { return extractSurface(field, frame); });
    if (!mesh.triangles.empty()) finish(mesh);
    return mesh;
  };
  TriangleMesh mesh = surface();
  if (!meshVolume || mesh.triangles.empty()) return mesh;
  const double volume = areaAndSignedVolume(mesh).signedVolume;
  if (std::abs(volume - *meshVolume) <= volumeCloseEnough * *meshVolume) return mesh;
  const double wanted = meshVolumeShift(*meshVolume, volume, volumePerShift(field, frame, mesh), mostTriangleBias);
  const double d = std::clamp(shift + wanted, -maxVolumeShift, maxVolumeShift) - shift;
  if (d == 0.0) return mesh;
  shiftField(field, d);
  shift += d;
  log::verbose("the triangles enclosed " + std::to_string(100.0 * (volume / *meshVolume - 1.0)) +
               " % of the input's volume: the field shifted by " + std::to_string(d) + " voxels more");
  return surface();
}

Smoothed smoothOnTheGrid(const TriangleMesh& mesh, const GridFrame& frame, const std::filesystem::path& input,
                         const DenoiseOptions& o, int fewestForNoise, std::optional<double> meshVolume,
                         const SurfaceFinish& finish, const ComputeDevice& device, StageClock& clock)
{
  device.checkFits(frame.extent);
  device.warnThatTheGridsDistancesAreTheCpus();
  Volume field =
      clock.time("sdf", [&](Progress& progress) { return signedDistance(mesh, frame, {.progress = &progress}); });
  requireEnclosedVolume(field, input);  // else the empty result would be blamed on the smoothing
  returnFreedHeapMemory();              // the distances' work arrays, before the lattice's peak
  const double enclosed = o.keepVolume ? enclosedVoxels(field) : 0.0;  // the mesh's, before any --noise
  addFieldNoise(field, o.noise);
  auto solver = clock.time("setup", [&] { return device.makeSolver(frame.extent); });
  SmoothedField<Volume> smoothed = clock.time(
      "lbm", [&](Progress& progress) { return smooth(*solver, std::move(field), o, fewestForNoise, 0.0, progress); });
  solver.reset();  // its memory goes before marching cubes takes its own
  double shift = o.keepVolume ? keepVolume(smoothed.field, enclosed) : 0.0;
  return {surfaceKeepingTheVolume(smoothed.field, frame, meshVolume, shift, finish, clock),
          {{"kind", "grid"}, {"cells", frame.extent.cells()}},
          frame.extent.cells(),
          smoothed.steps,
          smoothed.stepsRun,
          shift,
          false,
          std::move(smoothed.speeds),
          smoothed.twicingWeight,
          enclosed};
}

Smoothed smoothOnTheBand(const TriangleMesh& mesh, const GridFrame& frame, const std::filesystem::path& input,
                         const DenoiseOptions& o, int fewestForNoise, std::optional<double> meshVolume,
                         const SurfaceFinish& finish, const ComputeDevice& device, StageClock& clock)
{
  double halfWidth = bandHalfWidth(o);
  bool holesLeftOpen = false;  // a band wide enough to close them did not fit
  const BandRunKind kind{.paperRule = o.smoothing == Smoothing::Anisotropic};
  SignedDistanceStats distanceStats;
  BandField field = clock.time("sdf", [&](Progress& progress) {
    device.warmUpForTheBand(kind);  // the device opens while the distances are computed
    const bool perCellOmega = o.smoothing != Smoothing::Isotropic;
    const auto onTheBand = [&](double width, bool overHoles) {
      return signedDistanceBand(
          mesh, frame,
          {.halfWidth = width,
           .overHoles = overHoles,
           .progress = &progress,
           .checkBricks = [&](const BrickSet& b) { device.checkBandFits(b, perCellOmega, false); },
           .distancesFrom = [&](const TriangleBvh& tree) { return device.bandDistances(tree); }},
          &distanceStats);
    };
    BandField band =
        withFansWhereTheyFit([&](bool overHoles) { return onTheBand(halfWidth, overHoles); }, "the input's");
    // An open input's hole wider than the band: the surface that closes it
    // would be cut off (sdf/hole_radius.hpp). Widened over the widest hole,
    // and again while it still leaves (a closing surface that bulges).
    const double wholeGrid = glm::length(glm::dvec3(frame.extent.nx, frame.extent.ny, frame.extent.nz));
    while (surfaceLeavesTheBand(band) && halfWidth < wholeGrid) {
      const double wider = std::max(halfWidthOverHoles(mesh, frame.voxel, halfWidth), 2.0 * halfWidth);
      try {
        band = onTheBand(wider, true);
      } catch (const DeviceError& e) {
        // Refused before anything was allocated: the narrower band's
        // result, open over the hole, with what would close it.
        log::warning("the result is left open where the surface that closes the input's holes lies more than " +
                     std::to_string(int(halfWidth)) + " voxels from its triangles: a band " +
                     std::to_string(int(wider)) + " voxels wide would hold it, but " + e.what());
        holesLeftOpen = true;
        break;
      }
      halfWidth = wider;
      log::verbose("band widened to " + std::to_string(int(halfWidth)) +
                   " voxels to hold the surface that closes the input's holes");
    }
    return band;
  });
  requireEnclosedVolume(field, input);
  returnFreedHeapMemory();  // the distances' work arrays, before the lattice's peak
  const std::shared_ptr<const BrickSet> shared = field.sharedBricks();
  const BrickSet& bricks = *shared;
  const double enclosed = o.keepVolume ? enclosedVoxels(field) : 0.0;
  auto solver = clock.time("setup", [&] { return device.makeBandSolver(shared, kind); });
  SmoothedField<BandField> smoothed = clock.time("lbm", [&](Progress& progress) {
    return smooth(*solver, std::move(field), o, fewestForNoise, halfWidth, progress);
  });
  solver.reset();  // its memory goes before marching cubes takes its own
  double shift = o.keepVolume ? keepVolume(smoothed.field, enclosed) : 0.0;
  return {surfaceKeepingTheVolume(smoothed.field, frame, meshVolume, shift, finish, clock),
          {{"kind", "band"},
           {"half_width", halfWidth},
           {"holes_left_open", holesLeftOpen},
           {"bricks", bricks.activeCount()},
           {"cells", bricks.storedCells()},
           {"fraction_of_grid", double(bricks.storedCells()) / double(frame.extent.cells())}},
          bricks.storedCells(),
          smoothed.steps,
          smoothed.stepsRun,
          shift,
          distanceStats.onDevice,
          std::move(smoothed.speeds),
          smoothed.twicingWeight,
          enclosed};
}

}  // namespace

void checkGridAndNoise(const GridOptions& grid, const FieldNoise& noise)
{
  if (grid.voxel && !(*grid.voxel > 0.0 && std::isfinite(*grid.voxel)))
    throw UsageError(nameOf(Parameter::Voxel) + " must be a positive size");
  // A margin of a voxel at least: the surface's cells need neighbours.
  checkMargin(grid.marginVoxels, 1.0);
  if (!grid.voxel) checkResolution(grid.resolution, grid.marginVoxels);
  if (!(noise.amplitude >= 0.0 && noise.amplitude <= parameter_bounds::maxNoise))
    throw UsageError(nameOf(Parameter::Noise) + " must be from 0 to " + numberText(parameter_bounds::maxNoise) +
                     " (a fraction of the field's largest value; the paper adds 0.05), not " +
                     numberText(noise.amplitude));
}

void checkDenoiseOptions(const DenoiseOptions& o)
{
  relaxation::checkGamma(o.gamma);
  if (o.steps && (*o.steps < 0 || *o.steps > parameter_bounds::maxSteps))
    throw UsageError(nameOf(Parameter::Steps) + " must be from 0 to " + std::to_string(parameter_bounds::maxSteps));
  checkRadius(o.radius, o.steps.has_value());
  if (o.relaxRounds < 0 || o.relaxRounds > maxRelaxationRounds)
    throw UsageError(nameOf(Parameter::Relax) + " must be from 0 to " + std::to_string(maxRelaxationRounds));
  checkGridAndNoise(o.grid, o.noise);
  if (o.preview) render::requirePngPath(*o.preview, nameOf(Parameter::Preview));
}

void checkDenoiseFileArguments(const std::filesystem::path& output, const DenoiseOptions& o)
{
  checkDenoiseOptions(o);
  checkMeshFormat(output, o.compression);
  if (o.colourByCurvature) requireColourFormat(output, output.string());
}

void requireColourFormat(const std::filesystem::path& output, const std::string& what)
{
  const auto format = meshFormatOf(output);
  if (format != MeshFormat::Glb && format != MeshFormat::Gltf && format != MeshFormat::Obj && format != MeshFormat::Ply)
    throw UsageError(nameOf(Parameter::ColourByCurvature) +
                     " writes vertex colours into .glb, .gltf, .obj or .ply files, not " + what);
}

double colourByCurvature(TriangleMesh& mesh)
{
  const double scale = render::curvatureScale(mesh);
  mesh.colours = render::curvatureColours(mesh, scale);
  reportCurvatureColours(scale, "the mesh's");
  return scale;
}

void reportCurvatureColours(double scale, const std::string& whose)
{
  log::info("vertex colours: mean curvature from blue (-" + std::to_string(scale) + ") through grey (0) to red (+" +
            std::to_string(scale) + "), in 1 / the mesh's units; " + whose + " 95th percentile of |H|");
}

GridFrame placeGrid(const Bounds& bounds, const GridOptions& options)
{
  if (options.voxel) return frameWithVoxel(bounds, *options.voxel, options.marginVoxels);
  return frameWithResolution(bounds, options.resolution, options.marginVoxels);
}

namespace {

// A result whose volume is still far from what the input's field enclosed,
// after the volume was kept, lost parts the grid cannot hold (the Eight at
// --res 16: both holes closed, 55 % of its volume gone), which the user
// should not have to find by looking. Only where the field's volume changed
// too: a mesh that overlaps itself counts the overlap twice, and its union
// (the field's) is the right result. The figure is against the mesh's
// volume, as --json's volume_change (the field's count of voxels is coarse
// where parts are thin: the Knot at --res 14, 47 % against the mesh's 21 %).
void warnIfMuchVolumeWasLost(const TriangleMesh& result, std::optional<double> meshVolume, double inputFieldVoxels,
                             double voxel)
{
  if (!meshVolume || !(inputFieldVoxels > 0.0)) return;
  const double volume = areaAndSignedVolume(result).signedVolume;
  const double fieldChange = volume / (inputFieldVoxels * voxel * voxel * voxel) - 1.0;
  const double change = volume / *meshVolume - 1.0;
  if (std::abs(change) <= mostTriangleBias || std::abs(fieldChange) <= mostTriangleBias) return;
  std::ostringstream m;
  m << std::fixed << std::setprecision(0) << "the result encloses " << std::abs(change) * 100.0 << " % "
    << (change < 0 ? "less" : "more") << " volume than the input: parts thinner than about two voxels (voxel "
    << std::defaultfloat << std::setprecision(3) << voxel << ") " << (change < 0 ? "vanished" : "merged")
    << " on this grid; a finer " << nameOf(Parameter::Resolution) << " keeps them";
  log::warning(m.str());
}

// --steps auto: the amplitude of the noise along the input's normals, in
// voxels (analysis/normal_noise.hpp), and the fewest steps it asks for
// (smoothing_stop.hpp); none where the mesh has too few whole rings.
struct NoiseAmplitude {
  std::optional<double> voxels;
  int fewestSteps = 0;
};

NoiseAmplitude noiseAmplitude(const TriangleMesh& mesh, double voxel, double gamma, StageClock& clock)
{
  const std::optional<double> amplitude = clock.time("noise_amplitude", [&] { return normalNoiseAmplitude(mesh); });
  if (!amplitude) return {};
  const double voxels = *amplitude / voxel;
  const int fewest = smoothing_stop::fewestStepsForNoise(voxels, gamma);
  log::verbose("noise along the normals: " + std::to_string(voxels) + " voxels, at least " + std::to_string(fewest) +
               " steps");
  return {voxels, fewest};
}

// A surface that the smoothing made vanish: which steps did it, and what
// to change. Steps the user did not give are said to be chosen (by the
// noise, or by --radius), so that a batch user whose default denoise of a
// thin shell fails knows --steps (and --no-twicing) are theirs to set.
NumericalError vanished(const Smoothed& smoothed, const DenoiseOptions& given)
{
  const std::string steps = std::to_string(smoothed.steps) + (smoothed.steps == 1 ? " step" : " steps");
  std::string which = "after " + steps, change = "fewer " + nameOf(Parameter::Steps);
  if (given.radius) {
    which = "after the " + steps + " of " + nameOf(Parameter::Radius) + " " + numberText(*given.radius);
    change = "a smaller " + nameOf(Parameter::Radius);
  } else if (!given.steps) {
    which = "after the " + steps + " chosen for its noise" + (smoothed.twicingWeight ? " (twiced)" : "");
    change = "fewer " + nameOf(Parameter::Steps) +
             (smoothed.twicingWeight ? " (or turn " + nameOf(Parameter::Twicing) + " off)" : "");
  }
  return NumericalError("the smoothed surface vanished: no cell is inside " + which + "; give " + change +
                        ", a smaller " + nameOf(Parameter::Gamma) + " or a finer " + nameOf(Parameter::Resolution));
}

// The smoothing of denoiseMesh, its stages timed into `clock`, and the part
// of the report that is about the smoothing.
DenoiseResult smoothMesh(const TriangleMesh& mesh, const MeshTopology& topology, const std::filesystem::path& name,
                         const DenoiseOptions& given, const ComputeDevice& device, StageClock& clock)
{
  // From here on a --radius is the margin it widens and the steps it takes
  // on this grid.
  DenoiseOptions o = given;
  const GridFrame frame =
      given.radius ? gridForRadius(*given.radius, bounds(mesh), o.grid) : placeGrid(bounds(mesh), o.grid);
  log::verbose("grid " + frame.extent.toString() + ", voxel " + std::to_string(frame.voxel));
  if (given.radius) {
    o.steps = stepsForRadius(*given.radius / frame.voxel, given.gamma);
    log::verbose(nameOf(Parameter::Radius) + " " + std::to_string(*given.radius) + " = " +
                 std::to_string(*given.radius / frame.voxel) + " voxels: " + std::to_string(*o.steps) + " steps");
  }
  const bool dense = o.dense || o.noise.amplitude > 0.0;
  // The volume the output keeps where the input's own is known: a closed
  // manifold facing out (one facing in has no inside, winding number -1,
  // and is refused once its distances are known).
  // (Set by an if: GCC 12 took the conditional expression's optional for
  // maybe uninitialized.)
  std::optional<double> meshVolume;
  if (o.keepVolume && topology.closedManifold && topology.signedVolume > 0.0) meshVolume = topology.signedVolume;
  const SurfaceFinish relax = [&](TriangleMesh& triangles) {
    if (o.relaxRounds == 0) return;
    const RelaxationSummary relaxed = clock.time("relax", [&] { return relaxTriangles(triangles, o.relaxRounds); });
    log::verbose("triangles relaxed: " + std::to_string(o.relaxRounds) + " rounds, " +
                 std::to_string(relaxed.movedVertices) + " vertices moved in the last, " +
                 std::to_string(relaxed.keptVertices) + " kept so that no triangle turned over");
  };
  // Given steps, and --twicing's, which come from the field's speed alone,
  // need no amplitude.
  const NoiseAmplitude noise =
      o.steps || twicedAlways(o) ? NoiseAmplitude{} : noiseAmplitude(mesh, frame.voxel, o.gamma, clock);
  Smoothed smoothed = dense
                          ? smoothOnTheGrid(mesh, frame, name, o, noise.fewestSteps, meshVolume, relax, device, clock)
                          : smoothOnTheBand(mesh, frame, name, o, noise.fewestSteps, meshVolume, relax, device, clock);
  TriangleMesh result = std::move(smoothed.mesh);
  if (result.triangles.empty()) throw vanished(smoothed, given);
  warnIfMuchVolumeWasLost(result, meshVolume, smoothed.inputFieldVoxels, frame.voxel);
  std::optional<double> curvatureScale;
  if (o.colourByCurvature) clock.time("colour", [&] { curvatureScale = colourByCurvature(result); });
  if (!o.steps) relaxation::warnIfInaccurate(o.gamma, smoothed.steps);
  const double lbmMs = clock.ms("lbm");
  const double updates = double(smoothed.cells) * smoothed.stepsRun;
  nlohmann::json report = {
      {"grid",
       {{"size", {frame.extent.nx, frame.extent.ny, frame.extent.nz}},
        {"voxel", frame.voxel},
        {"origin", {frame.origin.x, frame.origin.y, frame.origin.z}}}},
      {"device", device.name()},
      {"gamma", o.gamma},
      {"steps", smoothed.steps},
      {"steps_chosen", given.radius ? "radius" : (o.steps ? "given" : "auto")},
      {"radius", given.radius ? nlohmann::json(*given.radius) : nlohmann::json(nullptr)},
      {"steps_run", smoothed.stepsRun},
      {"surface_speeds", smoothed.speeds},
      {"noise_amplitude_voxels", noise.voxels ? nlohmann::json(*noise.voxels) : nlohmann::json(nullptr)},
      {"noise_steps", noise.voxels ? nlohmann::json(noise.fewestSteps) : nlohmann::json(nullptr)},
      {"smoothing", smoothingName(o.smoothing)},
      {"twicing", smoothed.twicingWeight.has_value()},
      {"twicing_chosen", o.twicing ? "given" : "auto"},
      {"twicing_weight", smoothed.twicingWeight ? nlohmann::json(*smoothed.twicingWeight) : nlohmann::json(nullptr)},
      {"relax_rounds", o.relaxRounds},
      {"keep_volume", o.keepVolume},
      {"volume_shift_voxels", smoothed.volumeShift},
      {"noise", o.noise.amplitude},
      {"sdf_on", smoothed.distancesOnDevice ? "device" : "cpu"},
      {"lattice", smoothed.lattice},
      {"mlups", lbmMs > 0 && smoothed.stepsRun > 0 ? nlohmann::json(updates / (lbmMs * 1e3)) : nlohmann::json(nullptr)},
      {"curvature_scale", curvatureScale ? nlohmann::json(*curvatureScale) : nlohmann::json(nullptr)}};
  return {std::move(result), std::move(report)};
}

void warnIfFewGivenSteps(const DenoiseOptions& o)
{
  if (o.steps) relaxation::warnIfInaccurate(o.gamma, *o.steps);
}

// The report's figures of the input and the result, as `denoise --json`
// prints them (a file's path is added by its caller), and a warning where
// the result's parts differ from the input's.
void describeTheMeshes(nlohmann::json& report, const TriangleMesh& input, const MeshTopology& inputTopology,
                       const std::string& name, const TriangleMesh& result)
{
  sayWhereTheInputIsOpen(inputTopology, name, "the result closes it");
  const MeshTopology outputTopology = analyzeTopology(result);
  // Marching cubes closes every surface inside the lattice: an open result
  // ran out of it. The band says so itself where it could not widen.
  if (outputTopology.boundaryEdges > 0 && !report["lattice"].value("holes_left_open", false))
    log::warning("the result is open (" + std::to_string(outputTopology.boundaryEdges) +
                 " edges in one triangle only): the inside that " + name +
                 " encloses (its winding number above 1/2, which over an open mesh's holes may bulge past its rim) "
                 "reaches the edge of the grid; a wider " +
                 nameOf(Parameter::Margin) + " holds more of it");
  warnIfThePartsChanged(input, inputTopology, "the input", outputTopology, "the result",
                        report["grid"]["voxel"].get<double>());
  report["command"] = "denoise";
  report["input"] = meshSummary(input, inputTopology);
  report["output"] = meshSummary(result, outputTopology);
  report["volume_change"] = inputTopology.closedManifold && inputTopology.signedVolume != 0
                                ? nlohmann::json(outputTopology.signedVolume / inputTopology.signedVolume - 1.0)
                                : nlohmann::json(nullptr);
}

}  // namespace

DenoiseResult denoiseMesh(const TriangleMesh& mesh, const std::string& name, const DenoiseOptions& o,
                          const ComputeDevice& device)
{
  const log::WarningCollector warnings;
  const interrupt::CallStop ownStop(o.stop);
  checkDenoiseOptions(o);
  warnIfFewGivenSteps(o);
  // What readMesh checks of a file, for a mesh that comes from a program:
  // indices in range, finite coordinates, a surface that is not flat.
  TriangleMesh checked = mesh;
  validateInputMesh(checked, name);
  const ComputeDevice::Turn turn = device.takeTurn();
  StageClock clock([&device] { return device.deviceBusyMs(); });
  const MeshTopology inputTopology = orientTheInput(checked, name);
  DenoiseResult smoothed = smoothMesh(checked, inputTopology, name, o, device, clock);
  device.requireCleanValidation();
  describeTheMeshes(smoothed.report, checked, inputTopology, name, smoothed.mesh);
  smoothed.report["ms"] = clock.toJson();
  smoothed.report["device_ms"] = clock.deviceToJson();
  smoothed.report["warnings"] = warnings.warnings();
  return smoothed;
}

DenoiseResult denoiseFile(const std::filesystem::path& input, const std::filesystem::path& output,
                          const DenoiseOptions& o, const ComputeDevice& device)
{
  const log::WarningCollector warnings;
  const interrupt::CallStop ownStop(o.stop);
  checkDenoiseFileArguments(output, o);
  warnIfFewGivenSteps(o);
  checkNotTheInput(output, input, o.replaceInput);
  checkMeshDestination(output, o.compression);
  if (o.colourByCurvature) requireColourFormat(output, output.string());
  const ComputeDevice::Turn turn = device.takeTurn();
  if (o.preview) checkPreview(*o.preview, device);
  StageClock clock([&device] { return device.deviceBusyMs(); });
  clock.describeProgressWith([] { return std::string("nothing was written"); });  // until the commit

  TriangleMesh mesh = clock.time("read", [&] { return readMesh(input); });
  const MeshTopology inputTopology = orientTheInput(mesh, input.string());
  DenoiseResult smoothed = smoothMesh(mesh, inputTopology, input, o, device, clock);
  const TriangleMesh& result = smoothed.mesh;
  // The mesh goes under its name only once the preview is written too: a
  // preview that fails (a full disk) leaves neither file.
  const std::unique_ptr<AtomicFile> written =
      clock.time("write", [&] { return writeMeshUncommitted(result, output, EmptyMesh::Refused, o.compression); });
  device.requireCleanValidation();
  if (o.preview)
    clock.time("preview", [&] {
      writePreview({{&mesh, "input: " + input.filename().string()}, {&result, "output: " + output.filename().string()}},
                   render::parseView("front"), *o.preview, device);
    });
  // Not a stage of its own (a stop requested here would leave the preview
  // alone), but part of the writing's time.
  Stopwatch committing;
  try {
    commitMesh(*written, result.vertexCount(), result.triangleCount());
  } catch (...) {
    std::error_code ignored;
    if (o.preview) std::filesystem::remove(*o.preview, ignored);
    throw;
  }
  clock.record("write", committing.ms());

  nlohmann::json& report = smoothed.report;
  describeTheMeshes(report, mesh, inputTopology, input.string(), result);
  report["input"]["path"] = input.string();
  report["output"]["path"] = output.string();
  report["ms"] = clock.toJson();
  report["device_ms"] = clock.deviceToJson();
  report["preview"] = o.preview ? nlohmann::json(o.preview->string()) : nlohmann::json(nullptr);
  report["warnings"] = warnings.warnings();
  return smoothed;
}

}  // namespace lbmshape
