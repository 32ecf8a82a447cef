#include "lbmshape/gpu/gpu_context.hpp"

#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <sstream>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/host_memory.hpp"
#include "lbmshape/core/memory_sizes.hpp"
#include "lbmshape/core/parameter_names.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/stopwatch.hpp"

namespace lbmshape::gpu {
namespace {

uint32_t computeQueueFamily(const vk::raii::PhysicalDevice& device)
{
  auto families = device.getQueueFamilyProperties();
  // A compute-only family is often the asynchronous compute engine of a GPU;
  // any family with compute will do.
  for (uint32_t i = 0; i < families.size(); ++i)
    if ((families[i].queueFlags & vk::QueueFlagBits::eCompute) &&
        !(families[i].queueFlags & vk::QueueFlagBits::eGraphics))
      return i;
  for (uint32_t i = 0; i < families.size(); ++i)
    if (families[i].queueFlags & vk::QueueFlagBits::eCompute) return i;
  throw DeviceError("the Vulkan device has no compute queue");
}

// The family that draws: the compute one where it can, so that one queue
// serves both; otherwise the first with graphics, if any.
std::optional<uint32_t> graphicsQueueFamily(const vk::raii::PhysicalDevice& device, uint32_t computeFamily)
{
  auto families = device.getQueueFamilyProperties();
  if (families[computeFamily].queueFlags & vk::QueueFlagBits::eGraphics) return computeFamily;
  for (uint32_t i = 0; i < families.size(); ++i)
    if (families[i].queueFlags & vk::QueueFlagBits::eGraphics) return i;
  return std::nullopt;
}

}  // namespace

std::unique_ptr<GpuContext> GpuContext::open(const GpuOptions& options)
{
  auto instance = std::make_shared<VulkanInstance>(options.validation);
  size_t chosen = chooseDevice(instance->devices(), options.device);
  return std::make_unique<GpuContext>(std::move(instance), chosen);
}

GpuContext::GpuContext(std::shared_ptr<VulkanInstance> instance, size_t deviceIndex) : instance_(std::move(instance))
{
  if (const char* trace = std::getenv("LBMSHAPE_DEVICE_TRACE")) trace_ = std::strcmp(trace, "0") != 0;
  if (const char* staged = std::getenv("LBMSHAPE_STAGED_READBACK")) stagedReadback_ = std::strcmp(staged, "0") != 0;
  description_ = instance_->devices().at(deviceIndex);
  physical_ = &instance_->physicalDevice(deviceIndex);
  properties_ = physical_->getProperties();
  memoryProperties_ = physical_->getMemoryProperties();
  log::verbose("device: " + description_.name + " [" + description_.type + ", " + description_.driver + "]");

  queueFamily_ = computeQueueFamily(*physical_);
  const std::optional<uint32_t> graphicsFamily = graphicsQueueFamily(*physical_, queueFamily_);
  float priority = 1.0f;
  std::vector<vk::DeviceQueueCreateInfo> queueInfos{{{}, queueFamily_, 1, &priority}};
  if (graphicsFamily && *graphicsFamily != queueFamily_)
    queueInfos.emplace_back(vk::DeviceQueueCreateFlags(), *graphicsFamily, 1, &priority);
  // Wireframes are drawn as lines, where the device can.
  vk::PhysicalDeviceFeatures features;
  fillModeNonSolid_ = graphicsFamily && physical_->getFeatures().fillModeNonSolid;
  features.fillModeNonSolid = fillModeNonSolid_;
  device_ = vk::raii::Device(*physical_, vk::DeviceCreateInfo({}, queueInfos, {}, {}, &features));
  queue_ = vk::raii::Queue(device_, queueFamily_, 0);
  commandPool_ = vk::raii::CommandPool(
      device_, vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer, queueFamily_));
  if (graphicsFamily) {
    graphics_.emplace(Submission{
        vk::raii::Queue(device_, *graphicsFamily, 0),
        vk::raii::CommandPool(
            device_, vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer, *graphicsFamily))});
  }
  fence_ = vk::raii::Fence(device_, vk::FenceCreateInfo());
  // Two timestamps around each compute submission: the device's busy time,
  // beside the wall time, shows how long it waits for the host.
  if (physical_->getQueueFamilyProperties().at(queueFamily_).timestampValidBits > 0)
    timestamps_ = vk::raii::QueryPool(device_, vk::QueryPoolCreateInfo({}, vk::QueryType::eTimestamp, 2));
  pipelineCache_.emplace(device_, defaultPipelineCachePath(properties_));
  log::verbose(
      "pipeline cache: " + (pipelineCache_->path().empty() ? std::string("off") : pipelineCache_->path().string()) +
      " (" + std::to_string(pipelineCache_->loadedBytes()) + " bytes loaded)");
}

GpuContext::~GpuContext()
{
  // Work may still be queued if an exception unwound a solver mid-step.
  if (*device_) device_.waitIdle();
}

uint32_t GpuContext::memoryType(uint32_t typeBits, vk::MemoryPropertyFlags required,
                                vk::MemoryPropertyFlags preferred) const
{
  std::optional<uint32_t> fallback;
  for (uint32_t i = 0; i < memoryProperties_.memoryTypeCount; ++i) {
    if (!(typeBits & (1u << i))) continue;
    auto flags = memoryProperties_.memoryTypes[i].propertyFlags;
    if ((flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (!fallback) fallback = i;
  }
  if (!fallback) throw DeviceError("the Vulkan device has no suitable memory type for a buffer");
  return *fallback;
}

ComputeProgram& GpuContext::program(const ProgramSpec& spec)
{
  std::string key = spec.key();
  auto it = programs_.find(key);
  if (it != programs_.end()) return *it->second;
  requireRoomToCompile();
  Stopwatch watch;
  auto program = std::make_unique<ComputeProgram>(device_, pipelineCache_->cache(), spec);
  pipelineCreationMs_ += watch.ms();
  return *programs_.emplace(key, std::move(program)).first->second;
}

void GpuContext::requireRoomToCompile() const
{
  if (!description_.isCpu() || addressSpaceUnlimited()) return;
  const uint64_t left = hostMemoryBytes();
  if (left < compileHeadroomBytes)
    throw DeviceError("out of memory: " + mebibytes(left) + " of address space is left, and " + description_.name +
                      " needs about " + mebibytes(compileHeadroomBytes) +
                      " to compile its shaders; raise the limit (ulimit -v) or use a coarser grid (--res)");
}

void GpuContext::runAndWait(const std::function<void(vk::CommandBuffer)>& record)
{
  replayAndWait(this->record(record));
}

RecordedCommands GpuContext::record(const std::function<void(vk::CommandBuffer)>& commands)
{
  vk::raii::CommandBuffers buffers(device_,
                                   vk::CommandBufferAllocateInfo(*commandPool_, vk::CommandBufferLevel::ePrimary, 1));
  vk::raii::CommandBuffer cmd = std::move(buffers[0]);
  recordInto(cmd, {}, [&](vk::CommandBuffer c) {
    if (!*timestamps_) return commands(c);
    c.resetQueryPool(*timestamps_, 0, 2);
    c.writeTimestamp(vk::PipelineStageFlagBits::eTopOfPipe, *timestamps_, 0);
    commands(c);
    c.writeTimestamp(vk::PipelineStageFlagBits::eBottomOfPipe, *timestamps_, 1);
  });
  return RecordedCommands(std::move(cmd));
}

void GpuContext::replayAndWait(const RecordedCommands& commands)
{
  const double submittedAt = sinceCreated_.ms();
  submitAndWait(queue_, commands.handle());
  double deviceMs = 0.0;
  if (*timestamps_) {
    const auto [result, ticks] = timestamps_.getResults<uint64_t>(
        0, 2, 2 * sizeof(uint64_t), sizeof(uint64_t), vk::QueryResultFlagBits::e64 | vk::QueryResultFlagBits::eWait);
    if (result == vk::Result::eSuccess && ticks[1] >= ticks[0])
      deviceMs = double(ticks[1] - ticks[0]) * double(properties_.limits.timestampPeriod) * 1e-6;
  }
  deviceBusyMs_ += deviceMs;
  if (!trace_) return;
  const double doneAt = sinceCreated_.ms();
  std::ostringstream line;
  line << std::fixed << std::setprecision(3) << "device trace: submission " << ++submissions_;
  if (const char* label = TraceLabel::current()) line << " (" << label << ")";
  line << " at " << submittedAt << " ms, the host " << submittedAt - lastDoneMs_ << " ms since the last; the device "
       << deviceMs << " ms of " << doneAt - submittedAt << " ms waited";
  log::info(line.str());
  lastDoneMs_ = doneAt;
}

void GpuContext::requireDrawing(const std::string& otherwise) const
{
  if (!graphics_)
    throw DeviceError("the Vulkan device " + description_.name +
                      " cannot draw (it has no graphics queue); choose another with " + nameOf(Parameter::Device) +
                      otherwise);
}

void GpuContext::drawAndWait(const std::function<void(vk::CommandBuffer)>& record)
{
  requireDrawing();
  vk::raii::CommandBuffers buffers(
      device_, vk::CommandBufferAllocateInfo(*graphics_->pool, vk::CommandBufferLevel::ePrimary, 1));
  recordInto(buffers[0], vk::CommandBufferUsageFlagBits::eOneTimeSubmit, record);
  submitAndWait(graphics_->queue, *buffers[0]);
}

void GpuContext::recordInto(vk::raii::CommandBuffer& cmd, vk::CommandBufferUsageFlags usage,
                            const std::function<void(vk::CommandBuffer)>& record)
{
  cmd.begin(vk::CommandBufferBeginInfo(usage));
  // Whatever earlier submissions wrote is visible to this one: submissions
  // are ordered by the fence wait, but their memory needs this barrier.
  vk::MemoryBarrier previousWrites(vk::AccessFlagBits::eMemoryWrite,
                                   vk::AccessFlagBits::eMemoryRead | vk::AccessFlagBits::eMemoryWrite);
  cmd.pipelineBarrier(vk::PipelineStageFlagBits::eAllCommands, vk::PipelineStageFlagBits::eAllCommands, {},
                      previousWrites, {}, {});
  record(*cmd);
  cmd.end();
}

void GpuContext::submitAndWait(vk::raii::Queue& queue, vk::CommandBuffer cmd)
{
  try {
    queue.submit(vk::SubmitInfo({}, {}, cmd), *fence_);
    if (device_.waitForFences(*fence_, VK_TRUE, UINT64_MAX) != vk::Result::eSuccess)
      throw DeviceError("timed out waiting for the Vulkan device");
  } catch (...) {
    // The wait failed (out of host memory, under an address-space limit),
    // not the work: it may still run, and the exception is about to unwind
    // whoever owns the buffers it uses. They may go only once it ends (a
    // morph under `ulimit -v 800000` died of SIGSEGV in lavapipe's shader
    // threads, its buffers freed under them). The submission itself may
    // throw after the work was queued, too: the validation layer starts a
    // thread of its own at a queue's first submission, which under such a
    // limit fails with std::system_error (EAGAIN) out of vkQueueSubmit.
    try {
      queue.waitIdle();
    } catch (...) {
      device_.waitIdle();
    }
    throw;
  }
  device_.resetFences(*fence_);
}

namespace {
thread_local const char* currentLabel = nullptr;
}  // namespace

TraceLabel::TraceLabel(const char* what) : outer_(currentLabel)
{
  if (!currentLabel) currentLabel = what;
}
TraceLabel::~TraceLabel() { currentLabel = outer_; }
const char* TraceLabel::current() { return currentLabel; }

}  // namespace lbmshape::gpu
