#include "lbmshape/core/host_memory.hpp"

#include <sys/resource.h>
#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <optional>
#include <fstream>
#include <string>

#include "lbmshape/core/cgroup_memory.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/memory_sizes.hpp"

namespace lbmshape {
namespace {

// Bytes of address space this process maps now (/proc/self/statm's first field).
uint64_t mappedBytes()
{
  std::ifstream file("/proc/self/statm");
  uint64_t pages = 0;
  if (!(file >> pages)) return 0;
  return pages * uint64_t(sysconf(_SC_PAGE_SIZE));
}

// The process's address-space limit (`ulimit -v`), if one is set.
std::optional<uint64_t> addressSpaceLimit()
{
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  return uint64_t(limit.rlim_cur);
}

}  // namespace

uint64_t hostMemoryBytes()
{
  // Physical memory, not MemAvailable: that leaves out idle pages the
  // kernel would swap out and ZFS's cache, and would refuse on a desktop
  // jobs that run. A cgroup's limit, which the kernel enforces, counts
  // what its processes use.
  uint64_t bytes = uint64_t(sysconf(_SC_PHYS_PAGES)) * uint64_t(sysconf(_SC_PAGE_SIZE));
  if (const std::optional<uint64_t> left = cgroupMemoryLeft()) bytes = std::min(bytes, *left);
  if (const std::optional<uint64_t> limit = addressSpaceLimit()) {
    const uint64_t mapped = mappedBytes();
    bytes = std::min<uint64_t>(bytes, *limit > mapped ? *limit - mapped : 0);
  }
  return bytes;
}

bool addressSpaceUnlimited() { return !addressSpaceLimit(); }

int hostLongestSideThatFits(double neededBytes, const Extent3& extent, double power, double fixedBytes)
{
  const double allowed = double(hostMemoryBytes());
  return allowed > fixedBytes ? longestSideThatFits(extent, neededBytes - fixedBytes, allowed - fixedBytes, power) : 0;
}

void checkHostMemory(double neededBytes, const std::string& what, const Extent3& extent, double power,
                     double fixedBytes, int cap)
{
  const double allowed = double(hostMemoryBytes());
  if (neededBytes <= allowed) return;
  const std::string fits = allowed > fixedBytes
                               ? gridThatWouldFit(extent, neededBytes - fixedBytes, allowed - fixedBytes, power, cap)
                               : "no grid would fit beside the " + mebibytes(uint64_t(fixedBytes)) +
                                     " that any needs; raise the memory limit";
  throw DeviceError(what + " needs about " + mebibytes(uint64_t(neededBytes)) + " but this machine allows " +
                    mebibytes(uint64_t(allowed)) + "; " + fits);
}

void returnFreedHeapMemory()
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace lbmshape
