#include "lbmshape/gpu/device_description.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/parameter_names.hpp"

namespace lbmshape::gpu {

int typePreference(const std::string& type)
{
  if (type == "discrete") return 0;
  if (type == "integrated") return 1;
  if (type == "virtual") return 2;
  if (type == "cpu") return 3;
  return 4;
}

namespace {
std::string lowercase(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

std::string deviceList(const std::vector<DeviceDescription>& devices)
{
  std::string list;
  for (const auto& d : devices) list += (list.empty() ? "" : ", ") + std::to_string(d.index) + ": " + d.name;
  return list.empty() ? "none" : list;
}
}  // namespace

size_t chooseDevice(const std::vector<DeviceDescription>& devices, const std::string& request)
{
  if (devices.empty())
    throw DeviceError("no Vulkan device found; install a driver (on Debian: apt-get install mesa-vulkan-drivers)");
  if (request.empty()) {
    auto best = std::min_element(devices.begin(), devices.end(), [](const auto& a, const auto& b) {
      return typePreference(a.type) < typePreference(b.type);
    });
    return size_t(best - devices.begin());
  }
  unsigned index = 0;
  auto [end, ec] = std::from_chars(request.data(), request.data() + request.size(), index);
  if (ec == std::errc() && end == request.data() + request.size()) {
    for (size_t i = 0; i < devices.size(); ++i)
      if (devices[i].index == index) return i;
  } else {
    for (size_t i = 0; i < devices.size(); ++i)
      if (lowercase(devices[i].name).find(lowercase(request)) != std::string::npos) return i;
  }
  throw UsageError(nameOf(Parameter::Device) + " " + request + " matches no Vulkan device (have: " +
                   deviceList(devices) + ", or 'reference' for the CPU reference)");
}

}  // namespace lbmshape::gpu
