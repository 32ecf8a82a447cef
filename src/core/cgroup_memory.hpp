// What the memory cgroups a process is in leave it to allocate: a batch
// scheduler's job (Slurm), a systemd scope, a container. The limit that
// binds may be set on the process's own cgroup or on any above it, and the
// other processes in it use some of it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

namespace lbmshape {

// The least, over the cgroups from the process's own to the top, of the
// limit less what the cgroup uses now (less its page cache, which the
// kernel reclaims before it fails an allocation): cgroup v2's memory.max
// and memory.current, or v1's memory.limit_in_bytes and
// memory.usage_in_bytes. None where no cgroup on the way has a limit.
// `membership` is /proc/self/cgroup's text and `mountRoot` where the
// hierarchies are mounted (v1's memory controller under "memory"); a
// cgroup whose folder is not there (a container that shows its own cgroup
// as the root without a namespace) is looked for higher up.
std::optional<uint64_t> cgroupMemoryLeft(std::string_view membership, const std::filesystem::path& mountRoot);

// The same for this process.
std::optional<uint64_t> cgroupMemoryLeft();

}  // namespace lbmshape
