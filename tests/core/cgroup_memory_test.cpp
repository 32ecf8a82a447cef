// What the memory cgroups leave a process (core/cgroup_memory.hpp), on
// hierarchies laid out in a scratch folder as the kernel lays them out.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "lbmshape/core/cgroup_memory.hpp"
#include "support/scratch_folder.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& file, const std::string& text)
{
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// cgroup v2: the limit of a slice above the job's own scope binds, less
// what the slice uses that is not page cache. The job's own "max" is none.
TEST(CgroupMemory, AV2LimitAboveTheProcesssOwnCgroupBinds)
{
  testing::ScratchFolder root;
  write(root / "user.slice" / "memory.max", "1000000\n");
  write(root / "user.slice" / "memory.current", "300000\n");
  write(root / "user.slice" / "memory.stat", "anon 250000\nfile 100000\nkernel 1000\n");
  write(root / "user.slice" / "job.scope" / "memory.max", "max\n");
  write(root / "user.slice" / "job.scope" / "memory.current", "200000\n");
  EXPECT_EQ(cgroupMemoryLeft("0::/user.slice/job.scope\n", root.path()), 1000000u - 200000u);
}

// The least left over every limit on the way: two processes in a
// container whose limit is nearly used leave a third little.
TEST(CgroupMemory, TheLeastLeftOfSeveralLimitsBinds)
{
  testing::ScratchFolder root;
  write(root / "a" / "memory.max", "10000000\n");
  write(root / "a" / "memory.current", "1000000\n");
  write(root / "a" / "b" / "memory.max", "4000000\n");
  write(root / "a" / "b" / "memory.current", "3500000\n");
  EXPECT_EQ(cgroupMemoryLeft("0::/a/b\n", root.path()), 500000u);
}

// cgroup v1: the memory controller's own line and folder; "no limit" is a
// page count near 2^63; the page cache (total_cache) is not counted.
TEST(CgroupMemory, AV1MemoryControllersLimitIsRead)
{
  testing::ScratchFolder root;
  const fs::path memory = root / "memory";
  write(memory / "batch" / "job7" / "memory.limit_in_bytes", "9223372036854771712\n");
  write(memory / "batch" / "memory.limit_in_bytes", "500000\n");
  write(memory / "batch" / "memory.usage_in_bytes", "200000\n");
  write(memory / "batch" / "memory.stat", "cache 10000\nrss 150000\ntotal_cache 50000\ntotal_rss 150000\n");
  const std::string membership = "9:name=systemd:/\n4:memory:/batch/job7\n1:cpu:/\n0::/\n";
  EXPECT_EQ(cgroupMemoryLeft(membership, root.path()), 500000u - 150000u);
}

// A container that shows its own cgroup at the top without a cgroup
// namespace: the path named is not there, and the limit is found above.
TEST(CgroupMemory, ACgroupNotShownIsLookedForHigherUp)
{
  testing::ScratchFolder root;
  write(root / "memory.max", "4000000000\n");
  write(root / "memory.current", "1000000000\n");
  EXPECT_EQ(cgroupMemoryLeft("0::/docker/0123abcd\n", root.path()), 3000000000u);
}

TEST(CgroupMemory, NoLimitAnywhereIsNone)
{
  testing::ScratchFolder root;
  write(root / "a" / "memory.max", "max\n");
  write(root / "memory.max", "max\n");
  EXPECT_FALSE(cgroupMemoryLeft("0::/a\n", root.path()).has_value());
  EXPECT_FALSE(cgroupMemoryLeft("", root.path()).has_value());
  EXPECT_FALSE(cgroupMemoryLeft("not a cgroup line\n", root.path()).has_value());
}

// More used than the limit (a cgroup over it, being reclaimed) leaves nothing.
TEST(CgroupMemory, MoreUsedThanTheLimitLeavesNothing)
{
  testing::ScratchFolder root;
  write(root / "memory.max", "1000\n");
  write(root / "memory.current", "5000\n");
  EXPECT_EQ(cgroupMemoryLeft("0::/\n", root.path()), 0u);
}

}  // namespace
}  // namespace lbmshape
