// The driver's own shader cache (Mesa's, under XDG_CACHE_HOME), which
// lbmshape does not write but starts by starting a device.
#pragma once

#include <cstdint>
#include <filesystem>

namespace lbmshape::gpu {

// Where Mesa keeps its shader cache: MESA_SHADER_CACHE_DIR, else
// XDG_CACHE_HOME (absolute) or HOME's .cache, then mesa_shader_cache.
// Empty where none of them is set.
std::filesystem::path driverShaderCacheFolder();

// Whether the file system that holds (or would hold) `folder` has at least
// `leastFreeBytes` free: the nearest folder on its path that exists is
// asked. True where nothing can be asked (no such path): nothing is turned
// off on a guess.
bool hasRoomFor(const std::filesystem::path& folder, uint64_t leastFreeBytes);

// Mesa maps its cache's index file and writes through the mapping: on a
// file system with no room left, the write ends the process with SIGBUS
// (exit 135, no message; a whole jobs file lost), whatever lbmshape's own
// cache does. Where the cache's file system has under 64 MiB free, the
// driver's cache is turned off (MESA_SHADER_CACHE_DISABLE, unless the
// environment sets it) and a verbose line says so, once a process. Call
// before the first Vulkan instance, on a thread no other reads the
// environment beside (ComputeDevice's constructor does; the instance
// calls it again, for programs that make one alone).
void turnOffADriverShaderCacheWithoutRoom();

}  // namespace lbmshape::gpu
