// Which Vulkan device lbmshape uses: the best by type unless --device names
// one by index or by part of its name (pure logic, no Vulkan needed).
#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/gpu/device_description.hpp"

namespace lbmshape {
namespace {

gpu::DeviceDescription device(uint32_t index, const std::string& name, const std::string& type)
{
  gpu::DeviceDescription d;
  d.index = index;
  d.name = name;
  d.type = type;
  return d;
}

const std::vector<gpu::DeviceDescription> machine = {
    device(0, "llvmpipe (LLVM 15.0.6, 256 bits)", "cpu"),
    device(1, "Intel(R) UHD Graphics 630", "integrated"),
    device(2, "NVIDIA GeForce RTX 3060", "discrete"),
};

TEST(DeviceChoice, PrefersDiscreteThenIntegratedThenTheCpu)
{
  EXPECT_EQ(gpu::chooseDevice(machine, ""), 2u);
  EXPECT_EQ(gpu::chooseDevice({machine[0], machine[1]}, ""), 1u);
  EXPECT_EQ(gpu::chooseDevice({machine[0]}, ""), 0u);
}

TEST(DeviceChoice, ByIndexOrByPartOfTheNameInAnyCase)
{
  EXPECT_EQ(gpu::chooseDevice(machine, "0"), 0u);
  EXPECT_EQ(gpu::chooseDevice(machine, "1"), 1u);
  EXPECT_EQ(gpu::chooseDevice(machine, "llvmpipe"), 0u);
  EXPECT_EQ(gpu::chooseDevice(machine, "geforce"), 2u);
  EXPECT_EQ(gpu::chooseDevice(machine, "UHD"), 1u);
}

TEST(DeviceChoice, NoMatchIsAUsageErrorListingTheDevices)
{
  try {
    gpu::chooseDevice(machine, "radeon");
    FAIL() << "no device is called radeon";
  } catch (const UsageError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("radeon"), std::string::npos) << message;
    EXPECT_NE(message.find("2: NVIDIA GeForce RTX 3060"), std::string::npos) << message;
  }
  EXPECT_THROW(gpu::chooseDevice(machine, "7"), UsageError);
}

TEST(DeviceChoice, NoDeviceAtAllIsADeviceError) { EXPECT_THROW(gpu::chooseDevice({}, ""), DeviceError); }

}  // namespace
}  // namespace lbmshape
