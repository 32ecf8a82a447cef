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
  ~PipelineCacheFile();  // writes the cache back (temporary file, then rename)

  vk::raii::PipelineCache& cache() { return cache_; }
  const std::filesystem::path& path() const { return path_; }
  size_t loadedBytes() const { return loadedBytes_; }

private:
  std::filesystem::path path_;
  size_t loadedBytes_ = 0;
  vk::raii::PipelineCache cache_{nullptr};
};

// <cache dir>/pipelines-<pipelineCacheUUID>.bin, or empty when disabled by
// LBMSHAPE_NO_PIPELINE_CACHE=1 or when no cache directory is known.
std::filesystem::path defaultPipelineCachePath(const vk::PhysicalDeviceProperties& properties);

}  // namespace lbmshape::gpu
