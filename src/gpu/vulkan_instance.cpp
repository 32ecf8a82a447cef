#include "lbmshape/gpu/vulkan_instance.hpp"

#include <cstdlib>
#include <cstring>
#include <string>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/gpu/driver_modules.hpp"
#include "lbmshape/gpu/driver_shader_cache.hpp"

namespace lbmshape::gpu {
namespace {

constexpr const char* validationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* counter)
{
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    ++*static_cast<std::atomic<int>*>(counter);
    log::warning(std::string("vulkan validation: ") + (data->pMessage ? data->pMessage : "(no message)"));
  }
  return VK_FALSE;
}

std::string typeName(vk::PhysicalDeviceType type)
{
  switch (type) {
  case vk::PhysicalDeviceType::eDiscreteGpu: return "discrete";
  case vk::PhysicalDeviceType::eIntegratedGpu: return "integrated";
  case vk::PhysicalDeviceType::eVirtualGpu: return "virtual";
  case vk::PhysicalDeviceType::eCpu: return "cpu";
  default: return "other";
  }
}

std::string versionString(uint32_t v)
{
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

DeviceDescription describe(const vk::raii::PhysicalDevice& device, uint32_t index)
{
  auto chain = device.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceDriverProperties>();
  const auto& props = chain.get<vk::PhysicalDeviceProperties2>().properties;
  const auto& driver = chain.get<vk::PhysicalDeviceDriverProperties>();
  DeviceDescription d;
  d.index = index;
  d.name = props.deviceName.data();
  d.type = typeName(props.deviceType);
  d.driver = std::string(driver.driverName.data()) + " (" + driver.driverInfo.data() + ")";
  d.apiVersion = versionString(props.apiVersion);
  for (const auto& heap : device.getMemoryProperties().memoryHeaps)
    if (heap.flags & vk::MemoryHeapFlagBits::eDeviceLocal) d.deviceLocalBytes = std::max(d.deviceLocalBytes, heap.size);
  d.maxStorageBufferRange = props.limits.maxStorageBufferRange;
  d.maxTexelBufferElements = props.limits.maxTexelBufferElements;
  auto maintenance = device.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceMaintenance3Properties>();
  d.maxAllocationBytes = maintenance.get<vk::PhysicalDeviceMaintenance3Properties>().maxMemoryAllocationSize;
  for (int i = 0; i < 3; ++i) d.maxWorkgroupCount[i] = props.limits.maxComputeWorkGroupCount[i];
  return d;
}

bool layerAvailable(const vk::raii::Context& context, const char* name)
{
  for (const auto& layer : context.enumerateInstanceLayerProperties())
    if (std::strcmp(layer.layerName.data(), name) == 0) return true;
  return false;
}

}  // namespace

bool validationRequestedByEnvironment()
{
  const char* value = std::getenv("LBMSHAPE_VALIDATION");
  return value && std::strcmp(value, "0") != 0 && *value;
}

VulkanInstance::VulkanInstance(bool validation)
{
  validation = validation || validationRequestedByEnvironment();
  turnOffADriverShaderCacheWithoutRoom();
  vk::ApplicationInfo app("lbmshape", 1, "lbmshape", 1, VK_API_VERSION_1_1);
  std::vector<const char*> layers, extensions;
  if (validation) {
    if (!layerAvailable(context_, validationLayer))
      throw DeviceError(
          "Vulkan validation was requested but VK_LAYER_KHRONOS_validation is not installed "
          "(on Debian: apt-get install vulkan-validationlayers)");
    layers.push_back(validationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  // Synchronization validation catches missing barriers between the steps.
  std::array<vk::ValidationFeatureEnableEXT, 1> enabled = {vk::ValidationFeatureEnableEXT::eSynchronizationValidation};
  vk::ValidationFeaturesEXT features(enabled, {});
  vk::InstanceCreateInfo info({}, &app, layers, extensions, validation ? &features : nullptr);
  try {
    instance_ = vk::raii::Instance(context_, info);
  } catch (const vk::SystemError& e) {
    // The second hint is for headless NVIDIA machines, where the driver's own
    // manifest (libGLX_nvidia.so.0) can fail to start without a display
    // while its EGL library starts (docs/performance.md, "On a real GPU").
    throw DeviceError(std::string("cannot create a Vulkan instance (") + e.what() +
                      "); install a Vulkan driver (on Debian: apt-get install mesa-vulkan-drivers), or on a headless "
                      "NVIDIA machine point VK_DRIVER_FILES at a manifest naming libEGL_nvidia.so.0");
  }
  if (validation) {
    using Severity = vk::DebugUtilsMessageSeverityFlagBitsEXT;
    using Type = vk::DebugUtilsMessageTypeFlagBitsEXT;
    vk::DebugUtilsMessengerCreateInfoEXT messengerInfo({}, Severity::eWarning | Severity::eError,
                                                       Type::eGeneral | Type::eValidation | Type::ePerformance,
                                                       &onValidationMessage, validationMessages_.get());
    messenger_.emplace(instance_, messengerInfo);
  }
  vk::raii::PhysicalDevices physical(instance_);
  for (uint32_t i = 0; i < physical.size(); ++i) {
    devices_.push_back(describe(physical[i], i));
    physicalDevices_.push_back(std::move(physical[i]));
  }
  keepDriverModulesLoadedForLeakReports();
}

}  // namespace lbmshape::gpu
