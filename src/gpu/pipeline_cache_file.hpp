// The Vulkan pipeline cache, persisted under the user's cache directory so a
// second run can skip shader compilation where the driver supports it.
#pragma once

#include <filesystem>

#include <vulkan/vulkan_raii.hpp>

namespace lbmshape::gpu {

class PipelineCacheFile {
public:
  // An empty `path` keeps the cache in memory only.
  PipelineCacheFile(const vk::raii::Device& device, std::filesystem::path path);
  // Writes the cache back (temporary file, then rename) when the driver's
  // data differs from what was loaded: a run that compiled nothing new
  // writes nothing (on the H100 closing the device took 37-64 ms; a batch
  // of processes would otherwise rewrite the same file each).
  ~PipelineCacheFile();

  vk::raii::PipelineCache& cache() { return cache_; }
  const std::filesystem::path& path() const { return path_; }
  size_t loadedBytes() const { return loadedBytes_; }

private:
  std::filesystem::path path_;
  size_t loadedBytes_ = 0;
  size_t loadedHash_ = 0;  // std::hash of the loaded bytes
  vk::raii::PipelineCache cache_{nullptr};
};

// <cache dir>/pipelines-<pipelineCacheUUID>.bin, or empty when disabled by
// LBMSHAPE_NO_PIPELINE_CACHE=1 or when no cache directory is known.
std::filesystem::path defaultPipelineCachePath(const vk::PhysicalDeviceProperties& properties);

}  // namespace lbmshape::gpu
