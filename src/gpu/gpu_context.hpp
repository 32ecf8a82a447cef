// One Vulkan device ready for compute: the instance, the chosen physical
// device, a compute queue, a command pool, the persisted pipeline cache and
// the compiled compute programs; and, where the device can draw, a graphics
// queue for the pictures (render/). It outlives every buffer and solver made
// from it, and jobs in one process share it (and its compiled pipelines).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <vulkan/vulkan_raii.hpp>

#include "lbmshape/core/stopwatch.hpp"
#include "lbmshape/gpu/compute_program.hpp"
#include "lbmshape/gpu/device_description.hpp"
#include "lbmshape/gpu/pipeline_cache_file.hpp"
#include "lbmshape/gpu/recorded_commands.hpp"
#include "lbmshape/gpu/vulkan_instance.hpp"

namespace lbmshape::gpu {

struct GpuOptions {
  std::string device;       // --device: empty, an index, or part of a name
  bool validation = false;  // also on with LBMSHAPE_VALIDATION=1
};

class GpuContext {
public:
  // Opens device `deviceIndex` (into instance->devices()) of an instance
  // created, and its device chosen, beforehand.
  GpuContext(std::shared_ptr<VulkanInstance> instance, size_t deviceIndex);
  // A new instance and the device `options.device` names.
  static std::unique_ptr<GpuContext> open(const GpuOptions& options);
  ~GpuContext();
  GpuContext(const GpuContext&) = delete;
  GpuContext& operator=(const GpuContext&) = delete;

  const DeviceDescription& description() const { return description_; }
  const vk::PhysicalDeviceLimits& limits() const { return properties_.limits; }
  vk::raii::Device& device() { return device_; }
  vk::raii::Queue& queue() { return queue_; }
  const vk::raii::PhysicalDevice& physicalDevice() const { return *physical_; }
  int validationMessages() const { return instance_->validationMessages(); }
  const std::shared_ptr<VulkanInstance>& instance() const { return instance_; }
  bool validationEnabled() const { return instance_->validationEnabled(); }

  // Index of a memory type allowed by `typeBits` that has all `required` flags,
  // preferring one that also has the `preferred` ones.
  uint32_t memoryType(uint32_t typeBits, vk::MemoryPropertyFlags required,
                      vk::MemoryPropertyFlags preferred = {}) const;
  vk::MemoryPropertyFlags memoryFlags(uint32_t type) const { return memoryProperties_.memoryTypes[type].propertyFlags; }
  // LBMSHAPE_STAGED_READBACK=1: results come back through staging buffers
  // as on a discrete GPU, even where the device's memory is the host's
  // (MemoryUse::DeviceReadByHost is then exactly Device): the tests run
  // the discrete GPU's read-backs on lavapipe.
  bool stagedReadback() const { return stagedReadback_; }
  // Whether a copy between the host and the device crosses a bus, where
  // one large region moves far faster than many small ones (an NVIDIA H100's copy engine
  // moved one 2 KB region a brick at about 1 GB/s): any device but a CPU
  // one (lavapipe copies with memcpy), and any under
  // LBMSHAPE_STAGED_READBACK=1, so that lavapipe runs that path too.
  bool copiesCrossABus() const { return stagedReadback_ || !description_.isCpu(); }

  // The compiled program for this shader and specialization, built once.
  ComputeProgram& program(const ProgramSpec& spec);

  // Records commands into a fresh command buffer, submits it and waits.
  void runAndWait(const std::function<void(vk::CommandBuffer)>& record);
  // Records commands for the compute queue once, to be replayed as often
  // as wanted (gpu/recorded_commands.hpp); then submits them and waits.
  RecordedCommands record(const std::function<void(vk::CommandBuffer)>& commands);
  void replayAndWait(const RecordedCommands& commands);

  // Whether the device draws lines (fillModeNonSolid, for wireframes).
  bool canDrawLines() const { return fillModeNonSolid_; }
  // DeviceError, naming the device, unless it has a queue that draws (every
  // GPU and lavapipe do; a compute-only accelerator does not); `otherwise`
  // is added to the advice (what else the user can do).
  void requireDrawing(const std::string& otherwise = "") const;
  // The same as runAndWait, on the graphics queue (requireDrawing first).
  void drawAndWait(const std::function<void(vk::CommandBuffer)>& record);
  const vk::raii::PipelineCache& pipelineCache() { return pipelineCache_->cache(); }
  // Before a pipeline is compiled: on a CPU device (lavapipe) under an
  // address-space limit, DeviceError unless compileHeadroomBytes are left.
  // LLVM compiles there and does not survive running out: it crashed the
  // process (SIGSEGV) where a denoise under `ulimit -v 400000` left it less.
  void requireRoomToCompile() const;
  static constexpr uint64_t compileHeadroomBytes = uint64_t(96) << 20;

  // Time spent creating pipelines so far (ms): the start-up cost the
  // pipeline cache is there to cut.
  double pipelineCreationMs() const { return pipelineCreationMs_; }
  // The programs built so far (program() builds each once).
  size_t programsBuilt() const { return programs_.size(); }
  // Time the device spent on runAndWait's submissions so far (ms), from
  // timestamps written at their start and end; 0 where the queue has no
  // timestamps. Against the wall time of the same work it shows how long
  // the device waited for the host.
  double deviceBusyMs() const { return deviceBusyMs_; }
  size_t pipelineCacheLoadedBytes() const { return pipelineCache_->loadedBytes(); }

private:
  std::shared_ptr<VulkanInstance> instance_;
  DeviceDescription description_;
  vk::raii::PhysicalDevice* physical_ = nullptr;
  vk::PhysicalDeviceProperties properties_;
  vk::PhysicalDeviceMemoryProperties memoryProperties_;
  // A queue with its own command pool: compute, and graphics where that is
  // another family (one queue serves both where the family can do both).
  struct Submission {
    vk::raii::Queue queue{nullptr};
    vk::raii::CommandPool pool{nullptr};
  };
  // Begins `cmd` with the barrier that makes earlier submissions' writes
  // visible, records into it and ends it.
  static void recordInto(vk::raii::CommandBuffer& cmd, vk::CommandBufferUsageFlags usage,
                         const std::function<void(vk::CommandBuffer)>& record);
  void submitAndWait(vk::raii::Queue& queue, vk::CommandBuffer cmd);

  uint32_t queueFamily_ = 0;
  vk::raii::Device device_{nullptr};
  vk::raii::Queue queue_{nullptr};
  vk::raii::CommandPool commandPool_{nullptr};
  std::optional<Submission> graphics_;
  bool fillModeNonSolid_ = false;
  vk::raii::Fence fence_{nullptr};
  std::optional<PipelineCacheFile> pipelineCache_;
  std::map<std::string, std::unique_ptr<ComputeProgram>> programs_;
  double pipelineCreationMs_ = 0.0;
  vk::raii::QueryPool timestamps_{nullptr};  // two, around each compute submission
  double deviceBusyMs_ = 0.0;
  // LBMSHAPE_DEVICE_TRACE=1: a line on stderr for each compute submission,
  // its device time, its wait and the host's time since the last one.
  bool trace_ = false;
  bool stagedReadback_ = false;
  Stopwatch sinceCreated_;
  double lastDoneMs_ = 0.0;
  size_t submissions_ = 0;
};

// Names the compute submissions this thread makes while it lives, in
// LBMSHAPE_DEVICE_TRACE's lines ("band start", "band steps"). The
// outermost label names them all: a label inside another (the band's
// set-up within the device's warm-up) changes nothing.
class TraceLabel {
public:
  explicit TraceLabel(const char* what);
  ~TraceLabel();
  TraceLabel(const TraceLabel&) = delete;
  TraceLabel& operator=(const TraceLabel&) = delete;
  static const char* current();

private:
  const char* outer_;
};

}  // namespace lbmshape::gpu
