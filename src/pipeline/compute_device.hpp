// Where the lattice runs: a Vulkan device, or the CPU reference solver
// (--device reference). Jobs in one process share it, and with it the
// compiled pipelines. Nothing is opened until it is needed: the Vulkan
// instance (and the choice of device) when a grid is first checked against
// the device's limits, the device itself when the first solver is made; so
// bad input and impossible grids cost no device start-up.
#pragma once

#include <future>
#include <memory>
#include <thread>
#include <atomic>
#include <mutex>
#include <string>

#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/extent.hpp"
#include "lbmshape/lbm/band_solver.hpp"
#include "lbmshape/lbm/lattice_solver.hpp"
#include "lbmshape/sdf/band_signed_distance.hpp"
#include "lbmshape/sdf/triangle_bvh.hpp"

namespace lbmshape {

namespace gpu {
class GpuContext;
class VulkanInstance;
struct DeviceDescription;
}  // namespace gpu

// Where a stage with both a CPU and a device path runs: the band's unsigned
// distances (--sdf, bandDistances()), a morph's frames' marching cubes
// (--extract, surfacesOnTheDevice()). Auto lets the device's type decide.
enum class RunsOn { Auto, Cpu, Device };

// The rule behind both: whether `choice` runs a stage on the device, for a
// device of `type` (DeviceDescription::type; `reference` for the CPU
// reference solver, which has no device). Auto takes the device on a GPU
// (discrete, integrated or virtual) and the CPU on a CPU device such as
// lavapipe and on the reference. RunsOn::Device on the reference is a
// UsageError naming `option` (Parameter::Sdf, Parameter::Extract). (The band's distances also
// need their tree to fit the device: ComputeDevice::distancesOnTheDevice.)
bool runsOnTheDevice(RunsOn choice, bool reference, const std::string& type, Parameter option);

class ComputeDevice {
public:
  // `request`: empty (the best device), an index, part of a device name, or
  // "reference". Opening it later throws UsageError when nothing matches,
  // DeviceError when Vulkan is unusable.
  ComputeDevice(const std::string& request, bool validation, RunsOn distances = RunsOn::Auto,
                RunsOn surfaces = RunsOn::Auto);
  ~ComputeDevice();
  ComputeDevice(ComputeDevice&&) noexcept;

  std::string name() const;
  bool isReference() const { return request_ == "reference"; }
  // The chosen Vulkan device, opened on first use; null for the reference.
  gpu::GpuContext* gpu() const;
  // The Vulkan device's busy time so far (ms, GpuContext::deviceBusyMs); 0
  // before it is opened and for the reference.
  double deviceBusyMs() const;

  // The Vulkan device that draws pictures (render, --preview): the chosen
  // one, or for the reference solver the best there is, opened on first use.
  gpu::GpuContext& drawingContext() const;

  // A solver for a lattice of this size; throws UsageError when it does not
  // fit the device, before allocating anything.
  std::unique_ptr<LatticeSolver> makeSolver(const Extent3& extent) const;
  // The same check alone, for validating a job before its expensive stages;
  // for the reference solver, against the host's memory (DeviceError).
  void checkFits(const Extent3& extent) const;

  // A solver for the narrow band on these bricks.
  std::unique_ptr<BandSolver> makeBandSolver(std::shared_ptr<const BrickSet> bricks, BandRunKind kind = {}) const;
  // Throws DeviceError, saying what it needs and what grid would fit, when a
  // band on these bricks (with per-cell omega, a source) would not fit the
  // device: called as soon as the bricks are known, before their distances
  // are computed or anything is allocated for them.
  void checkBandFits(const BrickSet& bricks, bool perCellOmega, bool source) const;

  // Opens the Vulkan device and prepares the narrow band's pipelines for a
  // run of `kind` (makeBandSolver's) on a thread of its own, so that a
  // job's set-up overlaps its signed distance (lavapipe compiles a
  // pipeline in some 150 ms; a real GPU's driver takes long to start:
  // `lbmshape info` alone took 0.59 s on the H100).
  // Does nothing for the reference or once the device is open. A failure
  // there is left for the first real use to meet, where it would have come
  // without the warm-up, so errors stay what and where they were. Every
  // use of the device but description() (which a band's size check needs
  // while the distances are computed) waits for it to end.
  void warmUpForTheBand(BandRunKind kind) const;

  // Where a band's distances from this tree are computed: empty for the
  // CPU (band_distance.hpp), else the device's (device_band_distances.hpp),
  // one caller at a time. Auto picks the device on a GPU (discrete,
  // integrated or virtual), whose thousands of lanes walk the tree for
  // every cell faster than the host's cores, and the CPU for a CPU device
  // (lavapipe runs the same walk on the same cores, slower than the
  // native code with its shared hints) and for the reference; and the CPU
  // when the device cannot hold the tree. RunsOn::Device on the
  // reference is a UsageError, on a tree the device cannot hold a
  // DeviceError (when the distances are computed).
  UnsignedBandDistances bandDistances(const TriangleBvh& tree) const;
  bool distancesOnTheDevice(const TriangleBvh& tree) const;
  // For a job on the grid, whose distances have no device path: a warning
  // when --sdf device asked for one (a jobs file's other jobs may still
  // use it, so not an error).
  void warnThatTheGridsDistancesAreTheCpus() const;

  // Whether a morph on the band lists its frames' surfaces on the device
  // (shaders/band_surface.comp: a frame reads back its surface's pieces,
  // not its field, and the CPU makes the triangles). Auto: on a GPU, whose
  // transfers cost more than its pass, not on a CPU device (lavapipe, where
  // the field is read in place) nor the reference. RunsOn::Device on the
  // reference is a UsageError.
  bool surfacesOnTheDevice() const;
  // For a morph on the grid, whose frames have no device path: a warning
  // when --extract device asked for one.
  void warnThatTheGridsFramesAreTheCpus() const;

  // The library's calls that share a device take turns: denoiseMesh,
  // morphMeshes, drawMeshes and their file versions each hold the device's
  // turn from start to end, for its queue, command pools, pipelines and
  // warm-up serve one call at a time (two threads' first calls on one device
  // crashed in the warm-up). A call waits for the one before to end; a stop
  // request ends the wait (Interrupted). Calls meant to run at once open a
  // device each. A call within a call on the same thread (a denoise's
  // preview) shares its turn. A call checks its options, paths and meshes
  // before it takes the turn, so a bad one fails at once, busy device or not.
  using Turn = std::unique_lock<std::recursive_timed_mutex>;
  [[nodiscard]] Turn takeTurn() const;
  // The thread of a loop that takes a morph's frames as they come (Python's
  // iter_morph): a call from it on this device would wait for the morph,
  // which waits for the loop to take its next frame, and hung; it is a
  // UsageError instead. The loop sets it, and clears it (the default id)
  // when it ends.
  void setFramesLoopThread(std::thread::id thread) const { *framesLoop_ = thread; }

  // While one lives, on a morph's frame writer's thread around its frame
  // sink: a call there on the morph's own device would wait for the morph,
  // which waits for the sink, so it is a UsageError instead.
  class FrameSinkOf {
  public:
    explicit FrameSinkOf(const ComputeDevice& device);
    ~FrameSinkOf();
    FrameSinkOf(const FrameSinkOf&) = delete;
    FrameSinkOf& operator=(const FrameSinkOf&) = delete;

  private:
    const void* outer_;
  };

  // With validation on, throws DeviceError if the layer reported anything.
  void requireCleanValidation() const;
  // Destroys the Vulkan device (the instance stays, so that what the layer
  // reports while the device goes is still counted), then checks as above.
  void close();

private:
  const gpu::DeviceDescription& description() const;  // creates the instance, chooses the device
  // The chosen Vulkan device's context, opened if it is not yet: gpu()'s,
  // without waiting for the warm-up, whose thread calls it.
  gpu::GpuContext& openContext() const;
  void finishWarmUp() const;  // waits for warmUpForTheBand()'s thread, if any
  // runsOnTheDevice() for this device, `option` naming the choice.
  bool onTheDevice(RunsOn choice, Parameter option) const;
  bool distancesGoToTheDevice() const;  // the rule of bandDistances(), the tree aside

  std::string request_;
  bool validation_ = false;
  RunsOn distances_ = RunsOn::Auto;
  RunsOn surfaces_ = RunsOn::Auto;
  std::shared_ptr<std::recursive_timed_mutex> turn_ = std::make_shared<std::recursive_timed_mutex>();  // takeTurn()
  mutable std::shared_ptr<std::mutex> distancesTurn_ = std::make_shared<std::mutex>();  // bandDistances' callers
  std::shared_ptr<std::atomic<std::thread::id>> framesLoop_ = std::make_shared<std::atomic<std::thread::id>>();
  mutable std::mutex instanceMutex_;  // instance_ and chosen_, which the warm-up's thread sets too
  mutable std::shared_ptr<gpu::VulkanInstance> instance_;
  mutable size_t chosen_ = 0;
  mutable std::unique_ptr<gpu::GpuContext> gpu_;
  mutable std::future<void> warmUp_;  // the last member: the thread ends before the others go
};

}  // namespace lbmshape
