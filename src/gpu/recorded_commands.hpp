// Command buffers recorded once and submitted again and again. A solver's
// steps are the same dispatches every time (the same pipeline, descriptor
// sets and push constants, the two copies taking turns), so a step should
// cost a submission, not a recording: GpuContext::record once, then
// GpuContext::replayAndWait as often as the work repeats.
#pragma once

#include <cstring>
#include <functional>
#include <map>
#include <string>
#include <type_traits>

#include <vulkan/vulkan_raii.hpp>

namespace lbmshape::gpu {

class GpuContext;

class RecordedCommands {
public:
  explicit RecordedCommands(vk::raii::CommandBuffer buffer) : buffer_(std::move(buffer)) {}
  vk::CommandBuffer handle() const { return *buffer_; }

private:
  vk::raii::CommandBuffer buffer_;
};

// Recordings by what they were recorded for, as bytes (see keyOf). A
// recording refers to descriptor sets and buffers: writing a descriptor set
// it binds, or replacing a buffer, invalidates it, so whoever does either
// calls clear(). A cache holds at most `capacity` recordings and starts
// over beyond that (a morph's closing phase changes its push constants at
// every step: those recordings are used once).
class RecordedCommandCache {
public:
  explicit RecordedCommandCache(size_t capacity = 8) : capacity_(capacity) {}

  const RecordedCommands& get(GpuContext& context, const std::string& key,
                              const std::function<void(vk::CommandBuffer)>& record);
  void clear() { recordings_.clear(); }
  size_t size() const { return recordings_.size(); }
  size_t recorded() const { return recorded_; }  // recordings made so far, replays not counted

private:
  size_t capacity_;
  size_t recorded_ = 0;
  std::map<std::string, RecordedCommands> recordings_;
};

// The bytes of plain values (counts, push-constant structs), as a cache key.
template <typename... Parts>
std::string keyOf(const Parts&... parts)
{
  static_assert((std::is_trivially_copyable_v<Parts> && ...), "a key is made of plain values");
  std::string key;
  (key.append(reinterpret_cast<const char*>(&parts), sizeof(Parts)), ...);
  return key;
}

}  // namespace lbmshape::gpu
