#include "lbmshape/core/cgroup_memory.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>

namespace lbmshape {
namespace {

namespace fs = std::filesystem;

// The first number in a file; none for a missing file or "max".
std::optional<uint64_t> numberIn(const fs::path& file)
{
  std::ifstream in(file);
  uint64_t value = 0;
  if (in >> value) return value;
  return std::nullopt;
}

// The value of `key` in a memory.stat file ("file 123" lines); 0 where absent.
uint64_t statValue(const fs::path& file, std::string_view key)
{
  std::ifstream in(file);
  std::string name;
  uint64_t value = 0;
  while (in >> name >> value)
    if (name == key) return value;
  return 0;
}

struct Hierarchy {
  fs::path folder;  // of the process's cgroup
  bool v2;
};

// The memory hierarchy's folder of the process's cgroup: v2's "0::/path",
// or the v1 line whose controllers include "memory".
std::optional<Hierarchy> memoryHierarchy(std::string_view membership, const fs::path& mountRoot)
{
  std::istringstream lines{std::string(membership)};
  std::optional<Hierarchy> v2;
  for (std::string line; std::getline(lines, line);) {
    const size_t first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const fs::path path = fs::path(line.substr(second + 1)).relative_path();
    const auto under = [&](const fs::path& base) { return path.empty() ? base : base / path; };
    if (controllers.empty() && line.substr(0, first) == "0") {
      v2 = Hierarchy{under(mountRoot), true};
      continue;
    }
    std::istringstream names(controllers);
    for (std::string name; std::getline(names, name, ',');)
      if (name == "memory") return Hierarchy{under(mountRoot / "memory"), false};
  }
  return v2;
}

}  // namespace

std::optional<uint64_t> cgroupMemoryLeft(std::string_view membership, const fs::path& mountRoot)
{
  const std::optional<Hierarchy> hierarchy = memoryHierarchy(membership, mountRoot);
  if (!hierarchy) return std::nullopt;
  const fs::path top = hierarchy->v2 ? mountRoot : mountRoot / "memory";
  // v1 writes "no limit" as a page count near 2^63.
  constexpr uint64_t noLimit = uint64_t(1) << 62;
  std::optional<uint64_t> left;
  std::error_code error;
  for (fs::path at = hierarchy->folder;; at = at.parent_path()) {
    if (fs::is_directory(at, error)) {
      const std::optional<uint64_t> limit = numberIn(at / (hierarchy->v2 ? "memory.max" : "memory.limit_in_bytes"));
      if (limit && *limit < noLimit) {
        const uint64_t usage = numberIn(at / (hierarchy->v2 ? "memory.current" : "memory.usage_in_bytes")).value_or(0);
        const uint64_t cache = hierarchy->v2 ? statValue(at / "memory.stat", "file")
                                             : std::max(statValue(at / "memory.stat", "total_cache"),
                                                        statValue(at / "memory.stat", "cache"));
        const uint64_t used = usage > cache ? usage - cache : 0;
        const uint64_t here = *limit > used ? *limit - used : 0;
        left = std::min(left.value_or(UINT64_MAX), here);
      }
    }
    if (at == top || at.string().size() <= top.string().size()) break;  // the top, or a folder above it
  }
  return left;
}

std::optional<uint64_t> cgroupMemoryLeft()
{
  std::ifstream in("/proc/self/cgroup");
  std::stringstream text;
  text << in.rdbuf();
  return cgroupMemoryLeft(text.str(), "/sys/fs/cgroup");
}

}  // namespace lbmshape
