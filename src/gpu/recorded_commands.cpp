#include "lbmshape/gpu/recorded_commands.hpp"

#include "lbmshape/gpu/gpu_context.hpp"

namespace lbmshape::gpu {

const RecordedCommands& RecordedCommandCache::get(GpuContext& context, const std::string& key,
                                                  const std::function<void(vk::CommandBuffer)>& record)
{
  if (auto found = recordings_.find(key); found != recordings_.end()) return found->second;
  if (recordings_.size() >= capacity_) recordings_.clear();
  ++recorded_;
  return recordings_.emplace(key, context.record(record)).first->second;
}

}  // namespace lbmshape::gpu
