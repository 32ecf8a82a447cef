#include "lbmshape/pipeline/compute_device.hpp"

#include <chrono>
#include <system_error>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/host_memory.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/memory_sizes.hpp"
#include "lbmshape/gpu/driver_shader_cache.hpp"
#include "lbmshape/core/stopwatch.hpp"
#include "lbmshape/gpu/gpu_context.hpp"
#include "lbmshape/gpu/vulkan_instance.hpp"
#include "lbmshape/lbm/band_reference_solver.hpp"
#include "lbmshape/lbm/band_vulkan_solver.hpp"
#include "lbmshape/lbm/lattice_memory.hpp"
#include "lbmshape/lbm/reference_solver.hpp"
#include "lbmshape/lbm/vulkan_solver.hpp"
#include "lbmshape/sdf/device_band_distances.hpp"

namespace lbmshape {

ComputeDevice::ComputeDevice(const std::string& request, bool validation, RunsOn distances, RunsOn surfaces)
    : request_(request), validation_(validation), distances_(distances), surfaces_(surfaces)
{
  // On the caller's thread, before any warm-up thread starts the instance:
  // it may set an environment variable, which another thread must not be
  // reading meanwhile.
  gpu::turnOffADriverShaderCacheWithoutRoom();
}

ComputeDevice::~ComputeDevice() { finishWarmUp(); }

ComputeDevice::ComputeDevice(ComputeDevice&& other) noexcept
{
  other.finishWarmUp();  // its thread works on `other`
  request_ = std::move(other.request_);
  validation_ = other.validation_;
  distances_ = other.distances_;
  surfaces_ = other.surfaces_;
  turn_ = other.turn_;
  distancesTurn_ = other.distancesTurn_;
  framesLoop_ = other.framesLoop_;
  instance_ = std::move(other.instance_);
  chosen_ = other.chosen_;
  gpu_ = std::move(other.gpu_);
}

namespace {
// The turn of the device whose morph's frame sink runs on this thread.
thread_local const void* sinkOfTheMorphOn = nullptr;
}  // namespace

ComputeDevice::Turn ComputeDevice::takeTurn() const
{
  if (sinkOfTheMorphOn == turn_.get())
    throw UsageError(
        "a call from a morph's frame callback cannot use the morph's own device, which the morph holds until its last "
        "frame: give the call a device of its own");
  if (*framesLoop_ == std::this_thread::get_id())
    throw UsageError(
        "a call in a loop over a morph's frames cannot use the morph's own device, which the morph holds until its "
        "last frame, waiting for the loop to take the next: give the call a device of its own");
  Turn turn(*turn_, std::defer_lock);
  // Waited for in short spells, so that a stop request ends the wait.
  while (!turn.try_lock_for(std::chrono::milliseconds(50)))
    interrupt::check("nothing was done: the call was waiting for the device, which another call held");
  return turn;
}

ComputeDevice::FrameSinkOf::FrameSinkOf(const ComputeDevice& device) : outer_(sinkOfTheMorphOn)
{
  sinkOfTheMorphOn = device.turn_.get();
}

ComputeDevice::FrameSinkOf::~FrameSinkOf() { sinkOfTheMorphOn = outer_; }

void ComputeDevice::finishWarmUp() const
{
  if (!warmUp_.valid()) return;
  try {
    warmUp_.get();
  } catch (...) {
    // The first real use meets the same failure (warmUpForTheBand()).
  }
}

void ComputeDevice::warmUpForTheBand(BandRunKind kind) const
{
  if (isReference() || gpu_ || warmUp_.valid()) return;
  // Under an address-space limit there is no warm-up. The Vulkan loader and
  // driver are loaded here, on the caller's thread: loaded on the warm-up's,
  // a library constructor that throws (out of memory) leaves the dynamic
  // loader's lock held by a thread that then ends, and the next dlopen of
  // the process waits forever (a morph under `ulimit -v 150000` hung one run
  // in two). And the pipelines are compiled when first used, once the
  // distances' memory is returned, not beside them: LLVM (lavapipe) crashes
  // when an allocation fails, and the distances may take the room it counted
  // on (GpuContext::requireRoomToCompile). Without a limit both happen on
  // the warm-up's thread, beside the distances (lavapipe and its LLVM: 0.2 s
  // of one core, which was the first 0.2 s of a morph at 128^3).
  if (!addressSpaceUnlimited()) {
    try {
      description();
    } catch (...) {}
    return;  // a failure here: the first real use meets it
  }
  try {
    warmUp_ = std::async(std::launch::async, [this, kind] {
      // A band of one brick: its solver compiles the band's pipeline and runs
      // it once (lavapipe turns it into machine code then), for the GpuContext
      // to keep.
      const gpu::TraceLabel label("warm-up: the band's pipelines");
      // The distances' pipeline first: they come before the lattice.
      if (distancesGoToTheDevice()) prepareDeviceBandDistances(openContext());
      auto brick = std::make_shared<BrickSet>(Extent3{brickEdge, brickEdge, brickEdge});
      brick->activate(0, 0, 0);
      BandVulkanSolver warm(openContext(), std::move(brick), BandVulkanSolver::defaultStagingBytes, kind);
    });
  } catch (const std::system_error&) {
    // No thread to spare (an address-space limit leaves no room for its
    // stack): the device opens when first used, as without the warm-up.
  }
}

const gpu::DeviceDescription& ComputeDevice::description() const
{
  const std::lock_guard lock(instanceMutex_);
  if (!instance_) {
    auto instance = std::make_shared<gpu::VulkanInstance>(validation_);
    chosen_ = gpu::chooseDevice(instance->devices(), request_);
    instance_ = std::move(instance);
  }
  return instance_->devices()[chosen_];
}

double ComputeDevice::deviceBusyMs() const
{
  finishWarmUp();
  return gpu_ ? gpu_->deviceBusyMs() : 0.0;
}

gpu::GpuContext* ComputeDevice::gpu() const
{
  if (isReference()) return nullptr;
  finishWarmUp();
  return &openContext();
}

gpu::GpuContext& ComputeDevice::openContext() const
{
  if (!gpu_) {
    description();
    gpu_ = std::make_unique<gpu::GpuContext>(instance_, chosen_);
  }
  return *gpu_;
}

bool runsOnTheDevice(RunsOn choice, bool reference, const std::string& type, Parameter option)
{
  if (choice == RunsOn::Device && reference)
    throw UsageError(nameOf(option) + " device needs a Vulkan device, not the reference solver (" +
                     nameOf(Parameter::Device) + " reference)");
  if (choice == RunsOn::Cpu || reference) return false;
  return choice == RunsOn::Device || type != "cpu";
}

bool ComputeDevice::onTheDevice(RunsOn choice, Parameter option) const
{
  // Only Auto reads the device's type: the others open no instance.
  const bool readsType = choice == RunsOn::Auto && !isReference();
  return runsOnTheDevice(choice, isReference(), readsType ? description().type : std::string(), option);
}

bool ComputeDevice::distancesGoToTheDevice() const { return onTheDevice(distances_, Parameter::Sdf); }

bool ComputeDevice::distancesOnTheDevice(const TriangleBvh& tree) const
{
  if (!distancesGoToTheDevice()) return false;
  // Forced, a tree too large is deviceBandDistances()'s DeviceError.
  return distances_ == RunsOn::Device || deviceHoldsTree(description().maxStorageBufferRange, tree);
}

bool ComputeDevice::surfacesOnTheDevice() const { return onTheDevice(surfaces_, Parameter::Extract); }

void ComputeDevice::warnThatTheGridsFramesAreTheCpus() const
{
  if (surfaces_ == RunsOn::Device)
    log::warning(
        "--extract device lists the narrow band's surfaces; the grid's frames (--dense, --noise) are "
        "extracted on the CPU");
}

void ComputeDevice::warnThatTheGridsDistancesAreTheCpus() const
{
  if (distances_ == RunsOn::Device)
    log::warning("--sdf device computes the narrow band's distances; the grid's (--dense, --noise) are the CPU's");
}

UnsignedBandDistances ComputeDevice::bandDistances(const TriangleBvh& tree) const
{
  if (!distancesOnTheDevice(tree)) return {};
  return [this, turn = distancesTurn_](const TriangleBvh& bvh, const GridFrame& frame, const BandCells& cells,
                                       double maxVoxels) {
    const std::lock_guard lock(*turn);  // before gpu(), whose wait for the warm-up is one thread's
    gpu::GpuContext& context = *gpu();
    const gpu::TraceLabel label("the band's distances");
    return deviceBandDistances(context, bvh, frame, cells, maxVoxels);
  };
}

gpu::GpuContext& ComputeDevice::drawingContext() const
{
  if (!isReference()) return *gpu();
  if (!gpu_) {  // the reference never warms up
    if (!instance_) instance_ = std::make_shared<gpu::VulkanInstance>(validation_);
    chosen_ = gpu::chooseDevice(instance_->devices(), "");
    gpu_ = std::make_unique<gpu::GpuContext>(instance_, chosen_);
  }
  return *gpu_;
}

std::string ComputeDevice::name() const { return isReference() ? "reference (CPU)" : description().name; }

namespace {

// Host bytes a cell of the reference solvers needs, with what the job holds
// beside them: the grid's signed distance stage keeps about 30 B a cell at
// its peak (distance, nearest triangle, the far field's offers and lists,
// the sign's values), the grid solver two copies of 19 fp32 populations and
// the field, the band solver two copies of four moments and the field.
constexpr double gridReferenceBytesPerCell = 30 + 2 * 19 * 4 + 4;
constexpr double bandReferenceBytesPerCell = 30 + 2 * 16 + 4 + 1;

// Lavapipe allocates as it runs a dispatch (the frames of its shader
// threads) and does not check those allocations: under an address-space
// limit that leaves it less than this, a morph at `ulimit -v 800000` had 11
// MB left once its solver was made and died of SIGSEGV in the driver one
// run in ten. A solver that leaves less is refused, with exit 5, as any
// other allocation that fails.
constexpr uint64_t driverHeadroomBytes = uint64_t(64) << 20;

// What a Vulkan device's lattice takes of the host beside its buffers where
// the device's memory is the host's (lavapipe): the driver's room to
// compile and run.
constexpr double driverBytesBeside = double(driverHeadroomBytes + gpu::GpuContext::compileHeadroomBytes);

}  // namespace

void ComputeDevice::checkFits(const Extent3& extent) const
{
  LatticeLayout layout = latticeLayout(extent);
  if (!isReference()) {
    // On a device that is the CPU, two limits: each check names a grid that fits both.
    const bool cpu = description().isCpu();
    const double hostBytes = double(layout.totalBytes) + driverBytesBeside;
    checkFitsDevice(layout, description(),
                    cpu ? hostLongestSideThatFits(hostBytes, extent, 3.0, driverBytesBeside) : INT32_MAX);
    if (cpu)
      checkHostMemory(hostBytes, "the " + extent.toString() + " lattice on " + description().name, extent, 3.0,
                      driverBytesBeside, latticeLongestSideThatFits(extent, description()));
    return;
  }
  checkHostMemory(gridReferenceBytesPerCell * double(extent.cells()),
                  "the reference solver's " + extent.toString() + " grid", extent, 3.0);
}

namespace {

template <class Solver>
std::unique_ptr<Solver> withDriverHeadroom(std::unique_ptr<Solver> solver, bool deviceIsTheCpu)
{
  // Only a driver on the CPU allocates on the host as it runs, and only an
  // address-space limit fails those allocations where the driver cannot
  // see it (a discrete GPU's run was refused when the machine had little
  // memory available, with advice about ulimit -v).
  if (!deviceIsTheCpu || addressSpaceUnlimited()) return solver;
  const uint64_t left = hostMemoryBytes();
  if (left < driverHeadroomBytes)
    throw DeviceError("out of memory: " + mebibytes(left) + " of address space is left once the lattice is made, and " +
                      "the Vulkan driver needs about " + mebibytes(driverHeadroomBytes) +
                      " more to run it; raise the limit (ulimit -v) or use a coarser grid (--res)");
  return solver;
}

}  // namespace

std::unique_ptr<LatticeSolver> ComputeDevice::makeSolver(const Extent3& extent) const
{
  if (!isReference()) checkFitsDevice(latticeLayout(extent), description());
  if (!isReference())
    return withDriverHeadroom<LatticeSolver>(std::make_unique<VulkanSolver>(*gpu(), extent), description().isCpu());
  return std::make_unique<ReferenceSolver>(extent);
}

std::unique_ptr<BandSolver> ComputeDevice::makeBandSolver(std::shared_ptr<const BrickSet> bricks,
                                                          BandRunKind kind) const
{
  if (!isReference())
    return withDriverHeadroom<BandSolver>(
        std::make_unique<BandVulkanSolver>(*gpu(), std::move(bricks), BandVulkanSolver::defaultStagingBytes, kind),
        description().isCpu());
  return std::make_unique<BandReferenceSolver>(std::move(bricks));
}

void ComputeDevice::checkBandFits(const BrickSet& bricks, bool perCellOmega, bool source) const
{
  if (!isReference()) {
    // The staging buffer's size is the same on any grid.
    const double cellBytes = BandVulkanSolver::deviceBytesPerCell(perCellOmega, source) * double(bricks.storedCells());
    const double fixedBytes = driverBytesBeside + double(BandVulkanSolver::defaultStagingBytes);
    // On a device that is the CPU, two limits: each check names a grid that fits both.
    const bool cpu = description().isCpu();
    BandVulkanSolver::checkFits(
        bricks, description(), perCellOmega, source,
        cpu ? hostLongestSideThatFits(cellBytes + fixedBytes, bricks.cells(), 2.0, fixedBytes) : INT32_MAX);
    if (cpu)
      checkHostMemory(cellBytes + fixedBytes,
                      "the narrow band of " + std::to_string(bricks.storedCells()) + " cells on " + description().name,
                      bricks.cells(), 2.0, fixedBytes,
                      BandVulkanSolver::longestSideThatFits(bricks, description(), perCellOmega, source));
    return;
  }
  checkHostMemory(
      (bandReferenceBytesPerCell + (perCellOmega ? 4 : 0) + (source ? 4 : 0)) * double(bricks.storedCells()),
      "the reference solver's narrow band of " + std::to_string(bricks.storedCells()) + " cells", bricks.cells(), 2.0);
}

void ComputeDevice::requireCleanValidation() const
{
  finishWarmUp();
  const int messages = instance_ ? instance_->validationMessages() : 0;
  if (messages > 0)
    throw DeviceError("the Vulkan validation layer reported " + std::to_string(messages) +
                      " problem(s), printed above");
}

void ComputeDevice::close()
{
  finishWarmUp();
  if (gpu_) {
    // Saving the pipeline cache and the driver's own teardown happen here,
    // after the last stage's line: shown so that whole-process time adds up.
    Stopwatch closing;
    gpu_.reset();
    log::verbose("device closed in " + std::to_string(int(closing.ms())) + " ms");
  }
  requireCleanValidation();
}

}  // namespace lbmshape
