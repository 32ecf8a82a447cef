#include "lbmshape/gpu/pipeline_cache_file.hpp"

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <string_view>
#include <system_error>

#include <unistd.h>

#include "lbmshape/core/cache_directory.hpp"
#include "lbmshape/core/log.hpp"

namespace lbmshape::gpu {
namespace {
// Far above any driver's (lavapipe's for every pipeline lbmshape makes:
// under 2 MB).
constexpr uintmax_t largestPipelineCacheBytes = uintmax_t(256) << 20;
}  // namespace

std::filesystem::path defaultPipelineCachePath(const vk::PhysicalDeviceProperties& properties)
{
  if (const char* off = std::getenv("LBMSHAPE_NO_PIPELINE_CACHE"); off && std::strcmp(off, "0") != 0) return {};
  std::filesystem::path dir = userCacheDirectory();
  if (dir.empty()) return {};
  static const char* hex = "0123456789abcdef";
  std::string uuid;
  for (uint8_t byte : properties.pipelineCacheUUID) {
    uuid += hex[byte >> 4];
    uuid += hex[byte & 15];
  }
  return dir / ("pipelines-" + uuid + ".bin");
}

PipelineCacheFile::PipelineCacheFile(const vk::raii::Device& device, std::filesystem::path path)
    : path_(std::move(path))
{
  std::vector<char> data;
  // Only a regular file of a sensible size: the cache is optional, and a
  // named pipe there hung the start, a folder threw, a link to /dev/zero
  // ran out of memory.
  std::error_code ec;
  if (!path_.empty() && std::filesystem::is_regular_file(path_, ec) &&
      std::filesystem::file_size(path_, ec) <= largestPipelineCacheBytes && !ec) {
    try {
      std::ifstream in(path_, std::ios::binary);
      if (in) data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    } catch (const std::exception&) {
      data.clear();  // unreadable: as if there were none
    }
  }
  // The driver checks the header (vendor, device, UUID) and ignores data that
  // is not its own, so a stale or foreign file costs nothing but a recompile.
  vk::PipelineCacheCreateInfo info({}, data.size(), data.data());
  cache_ = vk::raii::PipelineCache(device, info);
  loadedBytes_ = data.size();
  loadedHash_ = std::hash<std::string_view>()(std::string_view(data.data(), data.size()));
}

PipelineCacheFile::~PipelineCacheFile()
{
  if (path_.empty() || !*cache_) return;
  try {
    std::vector<uint8_t> data = cache_.getData();
    const std::string_view bytes(reinterpret_cast<const char*>(data.data()), data.size());
    if (data.size() == loadedBytes_ && std::hash<std::string_view>()(bytes) == loadedHash_) return;
    std::error_code ec;
    std::filesystem::create_directories(path_.parent_path(), ec);
    std::filesystem::path temporary = path_;
    temporary += ".tmp" + std::to_string(::getpid());
    {
      std::ofstream out(temporary, std::ios::binary);
      out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
      if (!out) throw std::runtime_error("write failed");
    }
    std::filesystem::rename(temporary, path_);
  } catch (const std::exception& e) {
    // A cache that cannot be saved only makes the next start slower.
    log::verbose(std::string("pipeline cache not saved to ") + path_.string() + ": " + e.what());
  }
}

}  // namespace lbmshape::gpu
