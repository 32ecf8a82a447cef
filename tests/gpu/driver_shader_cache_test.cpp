// The driver's shader cache is turned off where its file system has no room
// (gpu/driver_shader_cache.hpp): Mesa ended the process with SIGBUS there.
#include <cstdlib>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "lbmshape/gpu/driver_shader_cache.hpp"
#include "support/scratch_folder.hpp"

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

// Sets an environment variable for the scope, then puts back what was there.
class ScopedVariable {
public:
  ScopedVariable(const char* name, const char* value) : name_(name)
  {
    if (const char* old = std::getenv(name)) old_ = old;
    value ? ::setenv(name, value, 1) : ::unsetenv(name);
  }
  ~ScopedVariable() { old_ ? ::setenv(name_, old_->c_str(), 1) : ::unsetenv(name_); }
  ScopedVariable(const ScopedVariable&) = delete;
  ScopedVariable& operator=(const ScopedVariable&) = delete;

private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(DriverShaderCache, IsWhereMesaKeepsIt)
{
  ScopedVariable dir("MESA_SHADER_CACHE_DIR", nullptr), xdg("XDG_CACHE_HOME", "/var/cache/me"),
      home("HOME", "/home/me");
  EXPECT_EQ(gpu::driverShaderCacheFolder(), fs::path("/var/cache/me/mesa_shader_cache"));
  {
    ScopedVariable relative("XDG_CACHE_HOME", "cache");  // not absolute: passed over, as Mesa does
    EXPECT_EQ(gpu::driverShaderCacheFolder(), fs::path("/home/me/.cache/mesa_shader_cache"));
  }
  ScopedVariable own("MESA_SHADER_CACHE_DIR", "/scratch/mesa");
  EXPECT_EQ(gpu::driverShaderCacheFolder(), fs::path("/scratch/mesa"));
}

// A folder not made yet is judged by the nearest one on its path that is.
TEST(DriverShaderCache, RoomIsAskedOfTheNearestFolderThatExists)
{
  testing::ScratchFolder folder;
  const fs::path unmade = folder / "not" / "yet" / "made";
  EXPECT_TRUE(gpu::hasRoomFor(unmade, 0));
  EXPECT_FALSE(gpu::hasRoomFor(unmade, UINT64_MAX));
  EXPECT_FALSE(gpu::hasRoomFor(folder.path(), UINT64_MAX));
}

// Turned off only where the file system is short of room, and never
// against what the environment says.
TEST(DriverShaderCache, IsTurnedOffOnlyWithoutRoom)
{
  testing::ScratchFolder folder;
  ScopedVariable dir("MESA_SHADER_CACHE_DIR", folder.path().c_str()), off("MESA_SHADER_CACHE_DISABLE", nullptr);
  gpu::turnOffADriverShaderCacheWithoutRoom();
  // A test machine's scratch folder has 64 MiB free; this one must.
  ASSERT_TRUE(gpu::hasRoomFor(folder.path(), uint64_t(64) << 20));
  EXPECT_EQ(std::getenv("MESA_SHADER_CACHE_DISABLE"), nullptr);
  {
    ScopedVariable full("MESA_SHADER_CACHE_DIR", "/proc/lbmshape-no-room");  // procfs: no free blocks
    ASSERT_FALSE(gpu::hasRoomFor("/proc/lbmshape-no-room", uint64_t(64) << 20));
    gpu::turnOffADriverShaderCacheWithoutRoom();
    ASSERT_NE(std::getenv("MESA_SHADER_CACHE_DISABLE"), nullptr);
    EXPECT_EQ(std::string(std::getenv("MESA_SHADER_CACHE_DISABLE")), "true");
  }
  ScopedVariable chosen("MESA_SHADER_CACHE_DISABLE", "false");
  ScopedVariable full("MESA_SHADER_CACHE_DIR", "/proc/lbmshape-no-room");
  gpu::turnOffADriverShaderCacheWithoutRoom();
  EXPECT_EQ(std::string(std::getenv("MESA_SHADER_CACHE_DISABLE")), "false");
}

}  // namespace
}  // namespace lbmshape
