#include "info_command.hpp"

#include <cstdlib>
#include <iomanip>
#include <iostream>

#include "lbmshape/core/memory_sizes.hpp"
#include "lbmshape/core/process_settings.hpp"
#include "lbmshape/gpu/vulkan_instance.hpp"
#include "lbmshape/pipeline/compute_device.hpp"

namespace lbmshape::cli {
namespace {

nlohmann::json describe(const gpu::DeviceDescription& d, bool selected)
{
  return {{"index", d.index},
          {"name", d.name},
          {"type", d.type},
          {"driver", d.driver},
          {"api_version", d.apiVersion},
          {"device_local_bytes", d.deviceLocalBytes},
          {"max_storage_buffer_range", d.maxStorageBufferRange},
          {"max_texel_buffer_elements", d.maxTexelBufferElements},
          {"max_allocation_bytes", d.maxAllocationBytes},
          {"selected", selected}};
}

void runInfo(const CommonOptions& common)
{
  gpu::VulkanInstance instance(common.validation);
  const auto& devices = instance.devices();
  const bool reference = wantsReference(common);
  const size_t selected = reference ? devices.size() : gpu::chooseDevice(devices, common.device);
  // Where the stages with both paths run with the options given (--sdf,
  // --extract) on the selected device.
  const std::string type = reference ? "" : devices[selected].type;
  const auto where = [](bool device) { return device ? "device" : "cpu"; };
  const char* distancesOn = where(runsOnTheDevice(common.distances, reference, type, Parameter::Sdf));
  const char* framesOn = where(runsOnTheDevice(common.surfaces, reference, type, Parameter::Extract));

  if (common.json) {
    nlohmann::json list = nlohmann::json::array();
    for (size_t i = 0; i < devices.size(); ++i) list.push_back(describe(devices[i], i == selected));
    const char* waitPolicy =
        std::getenv("OMP_WAIT_POLICY");  // how OpenMP's idle threads wait (core/process_settings.hpp)
    common.report({{"version", LBMSHAPE_VERSION},
                   {"devices", list},
                   {"selected", reference ? nlohmann::json("reference") : nlohmann::json(devices[selected].index)},
                   {"validation", instance.validationEnabled()},
                   {"sdf_on", distancesOn},
                   {"extract_on", framesOn},
                   {"openmp_wait_policy", waitPolicy ? nlohmann::json(waitPolicy) : nlohmann::json(nullptr)},
                   {"malloc_huge_pages", mallocAsksForHugePages()}});
    return;
  }
  std::cout << "lbmshape " << LBMSHAPE_VERSION << "\n";
  for (size_t i = 0; i < devices.size(); ++i) {
    const auto& d = devices[i];
    std::cout << (i == selected ? "* " : "  ") << d.index << ": " << d.name << "\n"
              << "     type " << d.type << ", Vulkan " << d.apiVersion << ", driver " << d.driver << "\n"
              << "     memory " << mebibytes(d.deviceLocalBytes) << ", max storage buffer range "
              << mebibytes(d.maxStorageBufferRange) << "\n";
  }
  std::cout << (reference ? "* " : "  ") << "reference: the CPU reference solver (--device reference)\n";
  std::cout << "band distances on: " << distancesOn << " (--sdf); morph frames extracted on: " << framesOn
            << " (--extract)\n";
}

}  // namespace

void addInfoCommand(CLI::App& app, const CommonOptions& common)
{
  auto* info = app.add_subcommand("info", "List the Vulkan devices and the one lbmshape selects (marked *)");
  info->callback([&common] { runInfo(common); });
}

}  // namespace lbmshape::cli
