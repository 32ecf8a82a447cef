// The --json results that scripts rely on: one object on stdout, with the
// keys the documentation promises, and values that make sense together.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_runner.hpp"

namespace lbmshape {
namespace {

nlohmann::json parseStdout(const testing::CliResult& r)
{
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(r.out);  // throws, failing the test, unless it is exactly one JSON document
}

TEST(JsonResults, InfoListsDevicesAndTheSelectedOne)
{
  auto j = parseStdout(testing::runLbmshape({"info", "--json"}));
  ASSERT_FALSE(j["devices"].empty());
  int selected = 0;
  for (const auto& d : j["devices"]) {
    for (const char* key : {"index", "name", "type", "driver", "device_local_bytes", "max_storage_buffer_range"})
      EXPECT_TRUE(d.contains(key)) << key;
    selected += d["selected"].get<bool>();
  }
  EXPECT_EQ(selected, 1);
  EXPECT_TRUE(j["validation"].get<bool>()) << "tests run with the validation layer";
}

TEST(JsonResults, BenchReportsConsistentFigures)
{
  auto j = parseStdout(testing::runLbmshape({"bench", "--json", "--size", "24,20,16", "--steps", "5", "--runs", "2"}));
  EXPECT_EQ(j["size"], (nlohmann::json{24, 20, 16}));
  EXPECT_EQ(j["steps"], 5);
  EXPECT_EQ(j["bytes_per_update"], 152);
  const double cells = 24 * 20 * 16;
  for (const char* backend : {"vulkan", "reference"}) {
    const auto& b = j[backend];
    ASSERT_TRUE(b.is_object()) << backend;
    EXPECT_GT(b["ms_per_step"].get<double>(), 0.0);
    EXPECT_NEAR(b["mlups"].get<double>(), cells / (b["ms_per_step"].get<double>() * 1e3), 1e-6 * b["mlups"].get<double>());
  }
  EXPECT_NEAR(j["vulkan"]["gbps"].get<double>(), j["vulkan"]["mlups"].get<double>() * 152e-3, 1e-6);
  EXPECT_NEAR(j["vulkan_over_reference"].get<double>(),
              j["vulkan"]["mlups"].get<double>() / j["reference"]["mlups"].get<double>(), 1e-9);
  EXPECT_GT(j["roofline_fraction"].get<double>(), 0.0);
  EXPECT_GT(j["memory_bandwidth"]["gbps"].get<double>(), 0.1);
}

TEST(JsonResults, ReferenceDeviceRunsWithoutVulkan)
{
  auto j = parseStdout(
      testing::runLbmshape({"--device", "reference", "bench", "--json", "--size", "12,12,12", "--steps", "3", "--runs", "1"}));
  EXPECT_TRUE(j["vulkan"].is_null());
  EXPECT_GT(j["reference"]["mlups"].get<double>(), 0.0);
}

}  // namespace
}  // namespace lbmshape
