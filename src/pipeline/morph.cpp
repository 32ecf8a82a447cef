#include "lbmshape/pipeline/morph.hpp"

#include <sstream>
#include <iomanip>
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <system_error>
#include <tuple>

#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/number_text.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/parameter_bounds.hpp"
#include "lbmshape/core/host_memory.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/stopwatch.hpp"
#include "lbmshape/lbm/relaxation.hpp"
#include "lbmshape/mesh/gltf_animation.hpp"
#include "lbmshape/mesh/mesh_format.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "lbmshape/mesh/mesh_validation.hpp"
#include "lbmshape/pipeline/animation_memory.hpp"
#include "lbmshape/pipeline/frame_writer.hpp"
#include "lbmshape/pipeline/input_orientation.hpp"
#include "lbmshape/pipeline/interruptible_steps.hpp"
#include "lbmshape/pipeline/morph_frame_report.hpp"
#include "lbmshape/pipeline/morph_folder.hpp"
#include "lbmshape/pipeline/morph_lattice.hpp"
#include "lbmshape/pipeline/morph_schedule.hpp"
#include "lbmshape/pipeline/parts_check.hpp"
#include "lbmshape/pipeline/staged_frames.hpp"
#include "lbmshape/pipeline/render_job.hpp"
#include "lbmshape/render/curvature_colours.hpp"
#include "lbmshape/render/png_file.hpp"
#include "lbmshape/pipeline/stage_clock.hpp"

namespace lbmshape {
namespace fs = std::filesystem;

namespace {

const char* alignmentName(Alignment a)
{
  switch (a) {
  case Alignment::None: return "none";
  case Alignment::Center: return "center";
  case Alignment::Fit: return "fit";
  }
  return "?";
}

// Moves (and for Fit scales) the target into the source's place.
struct Placement {
  glm::dvec3 fromCentre{0.0}, toCentre{0.0};
  double scale = 1.0;
  glm::dvec3 apply(const glm::dvec3& p) const { return toCentre + scale * (p - fromCentre); }
};

Placement placeTarget(const Bounds& source, const Bounds& target, Alignment align)
{
  Placement p;
  if (align == Alignment::None) return p;
  p.fromCentre = target.centre();
  p.toCentre = source.centre();
  if (align == Alignment::Fit && target.diagonal() > 0) p.scale = source.diagonal() / target.diagonal();
  return p;
}

// One line saying where the target went, when it moved: the last frame is
// the target as placed, not as it lies in its file.
void reportPlacement(const Placement& p, Alignment align, const fs::path& targetPath)
{
  const glm::dvec3 moved = p.toCentre - p.fromCentre;
  if (p.scale == 1.0 && moved == glm::dvec3(0.0)) return;
  std::ostringstream line;
  line << std::setprecision(4) << targetPath.filename().string() << " placed on the source ("
       << nameOf(Parameter::Align) << " " << alignmentName(align) << "): ";
  if (p.scale != 1.0) line << "scaled by " << p.scale << " about its centre" << (moved == glm::dvec3(0.0) ? "" : ", ");
  if (moved != glm::dvec3(0.0)) line << "moved by (" << moved.x << ", " << moved.y << ", " << moved.z << ")";
  line << "; the last frame is the target so placed";
  log::info(line.str());
}

// Frames made at the same step as the frame before are the same shape: a
// morph of few steps (a coarse grid, source and target close) for many
// frames plays in jerks.
// A shape less than a voxel across on the grid the two share (its size set
// by the larger) would enclose no cell: refused before the distances, naming
// the sizes and the way out. The message that came later, "it encloses no
// volume ... an open sheet has no inside", sent the user looking for holes.
void refuseShapesSmallerThanAVoxel(const TriangleMesh& source, const TriangleMesh& target, const fs::path& sourcePath,
                                   const fs::path& targetPath, double voxel, Alignment align)
{
  const auto across = [](const TriangleMesh& mesh) {
    const glm::dvec3 size = bounds(mesh).size();
    return std::max({size.x, size.y, size.z});
  };
  const double sourceSize = across(source), targetSize = across(target);
  const Bounds a = bounds(source), b = bounds(target);
  const glm::dvec3 bothSize3 = glm::max(a.max, b.max) - glm::min(a.min, b.min);
  const double bothSize = std::max({bothSize3.x, bothSize3.y, bothSize3.z});
  for (const auto& [path, size, other, otherSize] : {std::tuple{&sourcePath, sourceSize, &targetPath, targetSize},
                                                     std::tuple{&targetPath, targetSize, &sourcePath, sourceSize}}) {
    if (size >= voxel) continue;
    // The grid spans both shapes: the larger one sets it, or, where they
    // lie far apart, the distance between them does.
    const std::string setBy =
        bothSize > 1.01 * std::max(sourceSize, targetSize)
            ? "the two shapes set together, lying apart (" + threeSignificantDigits(bothSize) + " across both)"
            : other->string() + " (" + threeSignificantDigits(otherSize) + " across) sets";
    throw InputError(
        "cannot use " + path->string() + ": it is " + threeSignificantDigits(size) + " across, less than a voxel (" +
        threeSignificantDigits(voxel) + ") of the grid the two shapes share, whose size " + setBy +
        ", so it would enclose no cell" +
        (align != Alignment::Fit ? "; " + nameOf(Parameter::Align) + " fit scales the target onto the source" : ""));
  }
}

// Given steps fewer than the frames' intervals (the paper's scheme, frames
// on whole steps): some frames repeat the one before. Only an info line
// said so, and the clip held still in jerks.
void warnOfGivenStepsThatRepeatFrames(const MorphSchedule& schedule, int frames)
{
  const std::vector<int>& at = schedule.frameSteps();
  size_t repeats = 0;
  for (size_t k = 1; k < at.size(); ++k) repeats += at[k] == at[k - 1];
  if (repeats == 0) return;
  log::warning(std::to_string(repeats) + " of the " + std::to_string(frames) + " frames repeat the frame before: " +
               std::to_string(schedule.totalSteps()) + " steps are fewer than the " + std::to_string(frames - 1) +
               " intervals between frames; more " + nameOf(Parameter::Steps) +
               ", or none (a morph that arrives takes " + "as many steps between every two frames)");
}

// A morph that arrives takes the same number of steps between every two
// frames, one at least (MorphSchedule): its frames repeat only where it
// takes none. Where it scaled its steps for that, -v says so.
void sayHowTheFramesFallOnTheSteps(const MorphSchedule& schedule, int frames, double initialError, double tolerance)
{
  if (schedule.totalSteps() == 0 && frames > 1)
    log::warning("the source already lies within " + nameOf(Parameter::Tolerance) + " " + numberText(tolerance) +
                 " voxels of the target (" + threeSignificantDigits(initialError) +
                 "): the morph takes no step, and all " + std::to_string(frames) + " frames are the same shape");
  if (schedule.scale() != 1.0 && frames > 1)
    log::verbose("gamma and Cs scaled by " + threeSignificantDigits(schedule.scale()) + " so that the morph takes " +
                 std::to_string(schedule.totalSteps()) + " steps on the same way, " +
                 std::to_string(schedule.totalSteps() / (frames - 1)) + " between every two frames");
}

Bounds unite(const Bounds& a, const Bounds& b) { return {glm::min(a.min, b.min), glm::max(a.max, b.max)}; }

// The contact sheet of --preview: the source, six frames evenly chosen
// between the first and the last (both included), and the target as placed.
void writeMorphPreview(const TriangleMesh& source, const TriangleMesh& target, const std::vector<TriangleMesh>& frames,
                       const fs::path& sourcePath, const fs::path& targetPath, const fs::path& png,
                       const ComputeDevice& device)
{
  constexpr int shownFrames = 6;
  std::vector<ShownMesh> shown{{&source, "source: " + sourcePath.filename().string()}};
  for (size_t k : evenlySpaced(frames.size(), shownFrames)) shown.push_back({&frames[k], "frame " + std::to_string(k)});
  shown.push_back({&target, "target: " + targetPath.filename().string()});
  // From above at an angle: a morph often changes a shape in depth too.
  writePreview(shown, render::parseView("iso"), png, device);
}

// A source or target that is one of the folder's frames (a morph continued
// from the last frame of another into the same folder) would be removed or
// replaced by the frames: refused before any work.
void refuseInputsTheFramesReplace(const fs::path& folder, const fs::path& source, const fs::path& target)
{
  std::error_code ec;
  for (const auto& [input, what] : {std::pair{&source, "source"}, std::pair{&target, "target"}})
    if (isMorphOutputFile(*input) && fs::equivalent(fs::absolute(*input, ec).parent_path(), folder, ec))
      throw UsageError("cannot write the frames to " + folder.string() + ": the " + what + " " + input->string() +
                       " is one of the files a morph writes there (frame_*, morph.glb), which it would replace; "
                       "copy it elsewhere or write the frames to another folder");
}

// "5 to 9, 12": frame numbers in ascending order, runs shortened.
std::string frameRanges(const std::vector<int>& frames)
{
  std::string text;
  for (size_t i = 0; i < frames.size();) {
    size_t end = i;
    while (end + 1 < frames.size() && frames[end + 1] == frames[end] + 1) ++end;
    text += (text.empty() ? "" : ", ") + std::to_string(frames[i]);
    if (end > i) text += " to " + std::to_string(frames[end]);
    i = end + 1;
  }
  return text;
}

}  // namespace

void checkMorphOptions(const MorphOptions& o)
{
  relaxation::checkGamma(o.gamma);
  if (!(o.cs >= parameter_bounds::minCs && o.cs <= parameter_bounds::maxCs))
    throw UsageError(nameOf(Parameter::Cs) + " must be a morphing speed from " + numberText(parameter_bounds::minCs) +
                     " to " + numberText(parameter_bounds::maxCs) + " per step, not " + numberText(o.cs) +
                     " (the paper uses 0.1 to 0.3; at 1 each step closes two thirds of the distance to the target)");
  if (o.frames < 2 || o.frames > parameter_bounds::maxFrames)
    throw UsageError(nameOf(Parameter::Frames) + " must be from 2 (the source and the result) to " +
                     std::to_string(parameter_bounds::maxFrames));
  if (o.stepsPerFrame && o.steps)
    throw UsageError("give " + nameOf(Parameter::StepsPerFrame) + " or " + nameOf(Parameter::Steps) + ", not both");
  // A morph of no steps would only repeat the source; denoise --steps 0 is
  // the way to see a mesh on the grid unchanged.
  const std::string noSteps =
      " (with 0 steps every frame would be the source; " +
      std::string(parameterNaming() == ParameterNaming::CommandLine ? "lbmshape denoise --steps 0"
                                                                    : "a denoise of 0 steps") +
      " shows a mesh on the grid)";
  if (o.stepsPerFrame && *o.stepsPerFrame < 1)
    throw UsageError(nameOf(Parameter::StepsPerFrame) + " must be at least 1" + noSteps);
  if (o.steps && *o.steps < 1) throw UsageError(nameOf(Parameter::Steps) + " must be at least 1" + noSteps);
  const long total = givenStepCount(o);
  if (total > parameter_bounds::maxSteps)
    throw UsageError("the morph would run " + std::to_string(total) + " steps (" + nameOf(Parameter::Steps) + ", or " +
                     nameOf(Parameter::StepsPerFrame) + " times " + nameOf(Parameter::Frames) + " - 1); at most " +
                     std::to_string(parameter_bounds::maxSteps));
  if (!(o.fps > 0.0) || !std::isfinite(o.fps))
    throw UsageError(nameOf(Parameter::Fps) + " must be a positive, finite number of frames a second, not " +
                     numberText(o.fps));
  if (o.animation) {
    if (const std::string untimeable = untimeableInSinglePrecision(size_t(std::max(o.frames, 0)), o.fps);
        !untimeable.empty())
      throw UsageError(nameOf(Parameter::Fps) + " " + numberText(o.fps) + " does not fit the animation: " + untimeable);
  }
  if (!(o.tolerance > 0.0 && o.tolerance <= parameter_bounds::maxTolerance))
    throw UsageError(nameOf(Parameter::Tolerance) + " must be above 0 and at most " +
                     numberText(parameter_bounds::maxTolerance) + " voxel, not " + numberText(o.tolerance) +
                     " (a last frame further from the target's field than that is not at the target)");
  // ".obj" named frame_0000..obj: the extension is the format's, dot aside.
  if (!o.format.empty() && o.format.front() == '.')
    throw UsageError(nameOf(Parameter::Format) + " " + o.format + ": give the format without its dot (" +
                     o.format.substr(1) + ")");
  if (!meshFormatOf("x." + o.format))
    throw UsageError(nameOf(Parameter::Format) + " " + o.format +
                     " is not a mesh format (use glb, gltf, obj, ply, off or stl)");
  if (o.compression != GltfCompression::None && meshFormatOf("x." + o.format) != MeshFormat::Glb)
    throw UsageError(nameOf(Parameter::Compression) + " writes .glb frames, not " + nameOf(Parameter::Format) + " " +
                     o.format);
  if (o.colourByCurvature) requireColourFormat("x." + o.format, nameOf(Parameter::Format) + " " + o.format);
  checkGridAndNoise(o.grid, o.noise);
  if (o.preview) render::requirePngPath(*o.preview, nameOf(Parameter::Preview));
}

namespace {

// Where a morph's frames go: files in a folder, with the animation and the
// preview, or a program's FrameSink.
struct FrameDestination {
  MorphFolder* folder = nullptr;
  const FrameSink* sink = nullptr;
};

// The morph itself, from the meshes read (or given) to the report; `sourcePath`
// and `targetPath` name them in errors and in the report.
nlohmann::json runMorph(TriangleMesh source, TriangleMesh target, const fs::path& sourcePath,
                        const fs::path& targetPath, const MorphOptions& o, const ComputeDevice& device,
                        StageClock& clock, const FrameDestination& to)
{
  const MeshTopology sourceTopology = orientTheInput(source, sourcePath.string());
  // Moving and scaling the target below keeps its parts and genus.
  const MeshTopology targetTopology = orientTheInput(target, targetPath.string());
  const Placement placement = placeTarget(bounds(source), bounds(target), o.align);
  for (auto& p : target.positions) p = placement.apply(p);
  const GridFrame frame = placeGrid(unite(bounds(source), bounds(target)), o.grid);
  refuseShapesSmallerThanAVoxel(source, target, sourcePath, targetPath, frame.voxel, o.align);
  if (!o.band || o.noise.amplitude > 0.0) device.checkFits(frame.extent);
  log::verbose("grid " + frame.extent.toString() + ", voxel " + std::to_string(frame.voxel));

  // Before the fields are known, the longest the morph could run: no two
  // distances on the grid differ by more than its diagonal.
  const double gridDiagonal =
      std::sqrt(double(frame.extent.nx) * frame.extent.nx + double(frame.extent.ny) * frame.extent.ny +
                double(frame.extent.nz) * frame.extent.nz);
  const MorphSchedule longest = stepsGiven(o) ? MorphSchedule::fixed(o) : MorphSchedule::arriving(o, gridDiagonal);
  const std::unique_ptr<MorphLattice> lattice = makeMorphLattice(source, target, frame, o, longest, device, clock, [&] {
    // The preview's frames, and a compressed animation, hold every frame in
    // memory (a plain morph.glb is streamed to its file).
    if (o.preview)
      checkAnimationFits(source, target, frame.voxel, o.frames, FramesHeldBy::Preview);
    else if (o.animation && o.compression != GltfCompression::None)
      checkAnimationFits(source, target, frame.voxel, o.frames, FramesHeldBy::CompressedAnimation);
    if (to.folder && o.animation && o.compression == GltfCompression::None)
      checkAnimationFileFits(source, target, frame.voxel, o.frames);
  });
  returnFreedHeapMemory();  // the distances' work arrays, before the lattice's peak
  // A shape that encloses nothing is the input's fault, not the morph's.
  lattice->requireEnclosedVolumes(sourcePath, targetPath);
  // A frame within the tolerance of a target whose inside is shallower than
  // it may have no inside at all: a solid thinner than a voxel or two
  // (denoise refuses one thinner than a voxel as enclosing nothing).
  if (const double depth = lattice->targetDepth(); depth <= o.tolerance)
    throw InputError("cannot use " + targetPath.string() + " as the target: its inside reaches only " +
                     threeSignificantDigits(depth) + " voxels deep on this grid, not beyond " +
                     nameOf(Parameter::Tolerance) + " " + numberText(o.tolerance) +
                     ", so the morph could end with no surface; a solid this thin needs a "
                     "finer " +
                     nameOf(Parameter::Resolution) +
                     (audienceCanSet(Parameter::Voxel) ? " or " + nameOf(Parameter::Voxel) : std::string()));
  reportPlacement(placement, o.align, targetPath);  // once both are known to be shapes
  sayWhereTheInputIsOpen(sourceTopology, sourcePath.string(), "the frames close it");
  sayWhereTheInputIsOpen(targetTopology, targetPath.string(), "the frames close it");
  const double initialError = lattice->sourceErrorNearTarget();
  const MorphSchedule schedule = stepsGiven(o) ? longest : MorphSchedule::arriving(o, initialError);
  const std::vector<int>& frameSteps = schedule.frameSteps();
  if (!stepsGiven(o)) {
    log::verbose("the morph arrives in " + std::to_string(schedule.totalSteps()) + " steps (" +
                 std::to_string(initialError) + " voxels from the target to " + std::to_string(o.tolerance) + ")");
    sayHowTheFramesFallOnTheSteps(schedule, o.frames, initialError, o.tolerance);
  } else {
    warnOfGivenStepsThatRepeatFrames(schedule, o.frames);
  }
  TriangleMesh targetLevel = clock.time("extract", [&] { return lattice->targetLevel(); });
  // One colour scale for every frame, so that colours compare across them.
  // (A plain double, not an optional: GCC 12 sees an optional<double> here as
  // maybe uninitialized.)
  const double colourScale = o.colourByCurvature ? render::curvatureScale(targetLevel) : 0.0;
  if (o.colourByCurvature) reportCurvatureColours(colourScale, "the target's");
  MorphFrameReport frameReport(std::move(targetLevel), frame, o.frames, o.frameFigures);
  std::optional<StagedFrames> staged;
  if (to.folder) staged.emplace(to.folder->path());
  const std::optional<fs::path> framesFolder =
      staged ? std::optional<fs::path>(staged->destination()) : std::optional<fs::path>();
  lattice->start(device, o, schedule, clock);
  const bool framesAsPieces = lattice->framesAsSurfacePieces(frameReport.probeCells());
  if (framesAsPieces) log::verbose("frames: marching cubes on the device, only the surfaces' pieces read back");
  SteppingSolver& solver = lattice->solver();

  // The animation is assembled as the frames come, on the frame writer's
  // thread (a plain morph.glb streamed to its file): after the last frame
  // only its JSON is left to write (at 256^3 assembling and writing 48
  // frames took 0.81 s after the last one).
  std::optional<GltfAnimation> animation;
  if (framesFolder && o.animation)
    animation.emplace(*framesFolder / "morph.glb", size_t(o.frames), o.fps, o.compression);
  double figuresMs = 0.0, animationMs = 0.0;  // the writer's thread's, read after writer.finish()
  const FrameWriter::Keep keep = o.preview ? FrameWriter::Keep::EveryFrame : FrameWriter::Keep::LastFrame;
  const FrameWriter::Inspect inspect =
      o.frameFigures || animation ? FrameWriter::Inspect([&](int k, const FrameField& field, const TriangleMesh& mesh) {
        if (o.frameFigures) {
          const Stopwatch figures;
          frameReport.surface(k, field, mesh);
          figuresMs += figures.ms();
        }
        if (animation) {
          const Stopwatch assembly;
          animation->add(mesh);
          animationMs += assembly.ms();
        }
      })
                                  : FrameWriter::Inspect();
  const FrameWriter::Decorate decorate = o.colourByCurvature
                                             ? FrameWriter::Decorate([scale = colourScale](TriangleMesh& mesh) {
                                                 mesh.colours = render::curvatureColours(mesh, scale);
                                               })
                                             : FrameWriter::Decorate();
  std::optional<FrameWriter> frames;
  if (to.folder)
    frames.emplace(frame, *framesFolder, "." + o.format, o.frames, keep, inspect, o.compression, decorate);
  else
    frames.emplace(frame, *to.sink, o.frames, keep, inspect, decorate);
  FrameWriter& writer = *frames;
  InterruptibleSteps stepper(solver, o.stepsPerBatch);
  // Asked only when stopping: the frame being written is finished first, so
  // the count is what the folder holds.
  // "N complete frames in FOLDER", or where they replace an earlier morph's
  // files, that those stay.
  const auto framesDone = [&](int count) {
    const std::string done = std::to_string(count) + " complete frames";
    if (!to.folder) return done;
    return done + (staged->replacesEarlierFiles()
                       ? ", not kept: " + to.folder->path().string() + " keeps the earlier morph's files"
                       : " in " + to.folder->path().string());
  };
  const std::function<std::string()> whatWasDone = [&] {
    return framesDone(writer.stop()) + " (at step " + std::to_string(solver.stepsTaken()) + " of " +
           std::to_string(schedule.totalSteps()) + ")";
  };
  // Steps up to `step`, gamma and Cs following the schedule. A new Cs is
  // two push constants (setSourceStrength): set only when it changes
  // (start() set o.cs).
  double csNow = o.cs;
  const auto followSchedule = [&] {
    const int now = solver.stepsTaken();
    lattice->setGamma(schedule.gammaAt(now));
    if (schedule.csAt(now) != csNow) lattice->setMorphSpeed(csNow = schedule.csAt(now));
    return now;
  };
  const auto advanceTo = [&](int step) {
    while (solver.stepsTaken() < step) {
      const int now = followSchedule();
      stepper.advanceTo(std::min({step, schedule.sameStepsUntil(now), lattice->prepareSteps(now)}), whatWasDone);
    }
  };
  double lbmMs = 0.0, downloadMs = 0.0, waitedMs = 0.0;
  std::optional<int> convergedAt;
  double lastError = 0.0;
  Stopwatch sinceProgress, running;
  FrameField current;
  int currentStep = 0;          // the step of `current`: the solver may be one past it
  std::vector<int> madeAtStep;  // each frame's currentStep
  for (int k = 0; k < o.frames; ++k) {
    interrupt::check(whatWasDone);
    if (!convergedAt) {
      Stopwatch lbm;
      double deviceBefore = clock.deviceMsNow();
      advanceTo(frameSteps[size_t(k)]);
      currentStep = solver.stepsTaken();
      // Where the next frame is further on, its first step stores the field
      // it starts from: this frame's, with no field pass of its own (the
      // time is the lattice's; X counts half the source at the Cs of the
      // steps that made it, the step collides under its own). The last
      // frame's field is read alone.
      const bool stepFollows = k + 1 < o.frames && frameSteps[size_t(k) + 1] > currentStep;
      if (stepFollows) {
        lattice->setGamma(schedule.gammaAt(currentStep));
        csNow = schedule.csAt(currentStep);
        lattice->prepareSteps(currentStep);
        current = lattice->fieldThenStep(csNow);
      }
      lbmMs += lbm.ms();
      clock.recordDevice("lbm", clock.deviceMsNow() - deviceBefore);
      if (!stepFollows) {
        Stopwatch download;
        deviceBefore = clock.deviceMsNow();
        current = lattice->field();
        downloadMs += download.ms();
        clock.recordDevice("download", clock.deviceMsNow() - deviceBefore);
      }
      lastError = lattice->errorNearTarget(current);
      // Only the paper's scheme stops early: a morph that arrives spreads
      // its frames over the whole way, wherever the tolerance is reached.
      if (stepsGiven(o) && k > 0 && lastError < o.tolerance) {
        convergedAt = currentStep;
        // A warning: the clip holds still from here (75 % of it for
        // --steps 200 --frames 24), which a script keeping --json must see.
        if (k + 1 < o.frames)
          log::warning("converged at step " + std::to_string(*convergedAt) + " (max |X - X_target| " +
                       threeSignificantDigits(lastError) + " voxels near the target); frames " + std::to_string(k + 1) +
                       " to " + std::to_string(o.frames - 1) + " repeat it: fewer " + nameOf(Parameter::Steps) +
                       ", or none (a morph that arrives spreads its frames over the whole way)");
      }
    }
    const int step = currentStep;
    madeAtStep.push_back(step);
    frameReport.lattice(k, step, schedule.gammaAt(std::max(step - 1, 0)), schedule.csAt(std::max(step - 1, 0)),
                        lastError, lastError < o.tolerance);
    waitedMs += writer.push(k, current);
    if (sinceProgress.ms() > 1000.0) {
      log::info("frame " + std::to_string(k + 1) + "/" + std::to_string(o.frames) + ", " +
                std::to_string(int(solver.stepsTaken() / (running.ms() * 1e-3))) + " steps/s");
      sinceProgress.restart();
    }
  }
  // The writer's last frames, made and committed after the lattice's last
  // step: timed, so that the whole process's time adds up.
  clock.describeProgressWith(whatWasDone);
  std::vector<TriangleMesh> meshes = clock.time("last_frames", [&] { return writer.finish(); });
  clock.describeProgressWith([&] { return framesDone(o.frames); });
  const int steps = currentStep;  // the last frame's (a converged morph may have run one more)
  const double updates = double(lattice->cells()) * solver.stepsTaken();
  const nlohmann::json latticeDescription = lattice->describe();
  std::shared_ptr<const TriangleBvh> targetTree = lattice->targetTree();
  current = FrameField();
  lattice->finish();
  returnFreedHeapMemory();  // the lattice's and the fields' memory, before the animation's peak
  const std::vector<int> emptyFrames = writer.emptyFrames();
  if (!emptyFrames.empty())
    log::warning((emptyFrames.size() == 1 ? "frame " : "frames ") + frameRanges(emptyFrames) +
                 (emptyFrames.size() == 1 ? " has" : " have") +
                 " no surface: the shape vanished on its way (source and target barely overlap) and came back; "
                 "their files hold no triangles");
  clock.record("lbm", lbmMs);
  clock.record("download", downloadMs);
  clock.record("extract", writer.extractMs());
  clock.record("write", writer.writeMs());
  clock.record("commit", writer.commitMs());
  clock.record("frame_figures", figuresMs);
  StageClock::report("lbm", lbmMs, clock.deviceMs("lbm"));
  StageClock::report("extract", writer.extractMs());
  StageClock::report("write", writer.writeMs());
  if (writer.commitMs() > 0.0)
    log::verbose("the frames' commits (each file forced to disk, then renamed): " +
                 std::to_string(int(writer.commitMs())) + " ms");
  if (waitedMs > 0.0) log::verbose("the lattice waited " + std::to_string(int(waitedMs)) + " ms for the frame writer");

  interrupt::check(framesDone(o.frames));
  if (animation) {
    clock.record("animation", animationMs);
    log::verbose("animation: " + std::to_string(int(animationMs)) + " ms assembling it alongside the frames");
    clock.time("animation", [&] { animation->write(); });
  }
  if (staged) staged->commit();
  clock.describeProgressWith([&] {
    return to.folder ? "every frame" + std::string(animation ? " and the animation" : "") + " complete in " +
                           to.folder->path().string()
                     : "every frame made";
  });
  device.requireCleanValidation();
  if (to.folder && o.preview)
    clock.time("preview",
               [&] { writeMorphPreview(source, target, meshes, sourcePath, targetPath, *o.preview, device); });

  if (to.folder) to.folder->keep();
  const bool converged = lastError < o.tolerance;
  if (!converged && !stepsGiven(o))
    log::warning("the last frame is still up to " + std::to_string(lastError) + " voxels from the target's field (" +
                 nameOf(Parameter::Tolerance) + " " + std::to_string(o.tolerance) +
                 "); where the target's distance field has kinks (sharp concave edges, thin gaps) the lattice settles "
                 "a little off it; a larger " +
                 nameOf(Parameter::Tolerance) + " accepts that");

  const auto [final, arrival, last] = clock.time("final_figures", [&] {
    if (!targetTree) targetTree = std::make_shared<const TriangleBvh>(target, TriangleBvh::Queries::ClosestOnly);
    const TriangleBvh lastTree(meshes.back(), TriangleBvh::Queries::ClosestOnly);
    // Against what the grid can hold of the target, every vertex included:
    // how far the morph is from arriving.
    return std::tuple{
        compareSurfaces(meshes.back(), lastTree, target, *targetTree, ComparisonOptions{20000, 0.0, false}),
        frameReport.compareWithTargetLevel(meshes.back(), lastTree), analyzeTopology(meshes.back())};
  });
  warnIfThePartsChanged(target, targetTopology, "the target", last, "the last frame", frame.voxel);
  // A morph that starts at its target takes no step, and has no last one.
  const auto ofTheLastStep = [&](double value) {
    return schedule.totalSteps() > 0 ? nlohmann::json(value) : nlohmann::json(nullptr);
  };
  return {
      {"command", "morph"},
      {"source", sourcePath.string()},
      {"target", targetPath.string()},
      {"folder", to.folder ? nlohmann::json(to.folder->path().string()) : nlohmann::json(nullptr)},
      {"frames", o.frames},
      // The steps the frames were made at: the schedule's, but where the
      // lattice stopped early on arriving (given steps), the step it
      // stopped at for every later frame, as per_frame says.
      {"frame_steps", madeAtStep},
      {"steps", steps},
      {"schedule",
       {{"kind", stepsGiven(o) ? "given steps, constant gamma" : "arrive"},
        {"steps", schedule.totalSteps()},
        {"closing_from_step", schedule.annealed() ? nlohmann::json(schedule.annealFrom()) : nlohmann::json(nullptr)},
        {"final_gamma", ofTheLastStep(schedule.gammaAt(schedule.totalSteps() - 1))},
        {"final_cs", ofTheLastStep(schedule.csAt(schedule.totalSteps() - 1))},
        {"scale", schedule.scale()},
        {"initial_error_voxels", initialError}}},
      {"converged", converged},
      {"converged_at_step", convergedAt ? nlohmann::json(*convergedAt) : nlohmann::json(nullptr)},
      {"max_band_error_voxels", lastError},
      {"per_frame", frameReport.toJson()},
      {"empty_frames", emptyFrames},
      {"gamma", o.gamma},
      {"cs", o.cs},
      {"noise", o.noise.amplitude},
      {"lattice", latticeDescription},
      {"extract_on", framesAsPieces ? "device" : "cpu"},
      {"align",
       {{"mode", alignmentName(o.align)},
        {"scale", placement.scale},
        {"translation",
         {(placement.toCentre - placement.scale * placement.fromCentre).x,
          (placement.toCentre - placement.scale * placement.fromCentre).y,
          (placement.toCentre - placement.scale * placement.fromCentre).z}}}},
      {"grid",
       {{"size", {frame.extent.nx, frame.extent.ny, frame.extent.nz}},
        {"voxel", frame.voxel},
        {"origin", {frame.origin.x, frame.origin.y, frame.origin.z}}}},
      {"device", device.name()},
      {"ms", clock.toJson()},
      {"device_ms", clock.deviceToJson()},
      {"lattice_waited_for_writer_ms", waitedMs},
      {"mlups", lbmMs > 0 ? nlohmann::json(updates / (lbmMs * 1e3)) : nlohmann::json(nullptr)},
      {"final",
       {{"mean_distance_to_target", final.mean},
        {"mean_distance_to_target_voxels", final.mean / frame.voxel},
        {"hausdorff_to_target_voxels", final.hausdorff / frame.voxel},
        {"mean_distance_to_target_level_voxels", arrival.mean / frame.voxel},
        {"hausdorff_to_target_level_voxels", arrival.hausdorff / frame.voxel},
        {"closed_manifold", last.closedManifold},
        {"genus", last.genus ? nlohmann::json(*last.genus) : nlohmann::json(nullptr)},
        {"triangles", meshes.back().triangleCount()}}},
      {"animation",
       to.folder && o.animation ? nlohmann::json((to.folder->path() / "morph.glb").string()) : nlohmann::json(nullptr)},
      {"curvature_scale", o.colourByCurvature ? nlohmann::json(colourScale) : nlohmann::json(nullptr)},
      {"preview", to.folder && o.preview ? nlohmann::json(o.preview->string()) : nlohmann::json(nullptr)}};
}

}  // namespace

nlohmann::json morphFiles(const fs::path& sourcePath, const fs::path& targetPath, const fs::path& folder,
                          const MorphOptions& o, const ComputeDevice& device)
{
  const log::WarningCollector warnings;
  const interrupt::CallStop ownStop(o.stop);
  checkMorphOptions(o);
  MorphFolder out(folder, o.force);  // made and locked now: a second lbmshape fails before any work
  refuseInputsTheFramesReplace(folder, sourcePath, targetPath);
  const ComputeDevice::Turn turn = device.takeTurn();
  if (o.preview) checkPreview(*o.preview, device, folder);
  StageClock clock([&device] { return device.deviceBusyMs(); });
  TriangleMesh source = clock.time("read", [&] { return readMesh(sourcePath); });
  TriangleMesh target = clock.time("read", [&] { return readMesh(targetPath); });
  nlohmann::json report =
      runMorph(std::move(source), std::move(target), sourcePath, targetPath, o, device, clock, {.folder = &out});
  report["warnings"] = warnings.warnings();
  return report;
}

nlohmann::json morphMeshes(const TriangleMesh& source, const TriangleMesh& target, const MorphOptions& options,
                           const ComputeDevice& device, const FrameSink& sink)
{
  const log::WarningCollector warnings;
  const interrupt::CallStop ownStop(options.stop);
  MorphOptions o = options;
  o.animation = false;  // about files: the program has every frame
  o.preview.reset();
  checkMorphOptions(o);
  TriangleMesh checkedSource = source, checkedTarget = target;
  validateInputMesh(checkedSource, "the source mesh");
  validateInputMesh(checkedTarget, "the target mesh");
  if (!sink) throw UsageError("the morph's frame sink is empty: its frames would go nowhere");
  const ComputeDevice::Turn turn = device.takeTurn();
  StageClock clock([&device] { return device.deviceBusyMs(); });
  const FrameSink guarded = [&](int frame, const TriangleMesh& mesh) {
    const ComputeDevice::FrameSinkOf callsFromTheSink(device);
    sink(frame, mesh);
  };
  nlohmann::json report = runMorph(std::move(checkedSource), std::move(checkedTarget), "the source mesh",
                                   "the target mesh", o, device, clock, {.sink = &guarded});
  report["warnings"] = warnings.warnings();
  return report;
}

}  // namespace lbmshape
