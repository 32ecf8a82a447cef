#include "lbmshape/gpu/driver_shader_cache.hpp"

#include <sys/statvfs.h>

#include <cstdlib>
#include <string>
#include <system_error>

#include "lbmshape/core/log.hpp"

namespace lbmshape::gpu {
namespace {

namespace fs = std::filesystem;

const char* environment(const char* name)
{
  const char* value = std::getenv(name);
  return value && *value ? value : nullptr;
}

constexpr uint64_t leastRoomForTheDriversCache = uint64_t(64) << 20;

}  // namespace

fs::path driverShaderCacheFolder()
{
  if (const char* dir = environment("MESA_SHADER_CACHE_DIR")) return dir;
  if (const char* xdg = environment("XDG_CACHE_HOME"); xdg && fs::path(xdg).is_absolute())
    return fs::path(xdg) / "mesa_shader_cache";
  if (const char* home = environment("HOME")) return fs::path(home) / ".cache" / "mesa_shader_cache";
  return {};
}

bool hasRoomFor(const fs::path& folder, uint64_t leastFreeBytes)
{
  std::error_code error;
  for (fs::path at = folder; !at.empty(); at = at.parent_path()) {
    if (fs::exists(at, error)) {
      struct statvfs space {};
      if (::statvfs(at.c_str(), &space) != 0) return true;
      return uint64_t(space.f_bavail) * uint64_t(space.f_frsize) >= leastFreeBytes;
    }
    if (at == at.parent_path()) break;
  }
  return true;
}

void turnOffADriverShaderCacheWithoutRoom()
{
  if (environment("MESA_SHADER_CACHE_DISABLE")) return;  // the user's choice, either way (or this, done)
  const fs::path folder = driverShaderCacheFolder();
  if (folder.empty() || hasRoomFor(folder, leastRoomForTheDriversCache)) return;
  ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
  log::verbose("the driver's shader cache is off: the file system of " + folder.string() +
               " has under 64 MiB free, and Mesa ends the process (SIGBUS) when it fills");
}

}  // namespace lbmshape::gpu
