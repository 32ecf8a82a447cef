#include "lbmshape/core/process_settings.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

#include <sys/auxv.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <unistd.h>

#include "lbmshape/core/host_memory.hpp"

namespace lbmshape {
namespace {

constexpr const char* kHugePageTunable = "glibc.malloc.hugetlb";
// glibc gives each thread that allocates an arena of its own, up to 8 per
// core, each reserving 64 MB of address space: a denoise at --res 200 maps
// 913 MB for 100 MB of data, and under `ulimit -v` that reservation, not the
// data, is what runs out (lavapipe's LLVM then crashed compiling). Two
// arenas: 483 MB mapped (one: 417 MB, at the cost of every thread's
// allocations waiting on one lock).
constexpr int kArenasUnderAnAddressSpaceLimit = 2;

std::string environment(const char* name)
{
  const char* value = std::getenv(name);
  return value ? value : "";
}

}  // namespace

void restartWithProcessSettings(char** argv, bool hugePages)
{
  fitMallocToTheAddressSpace();
  // A set-user-ID or capability-raising start (AT_SECURE): glibc drops the
  // tunables there, so a restart would find them missing again, and again.
  if (getauxval(AT_SECURE)) return;
  bool changed = false;
  if (!std::getenv("OMP_WAIT_POLICY")) {
    setenv("OMP_WAIT_POLICY", "passive", 1);
    changed = true;
  }
  // GLIBC_TUNABLES is a colon-separated list: the user's other tunables
  // stay, and a hugetlb of their own (0 included) wins.
  const std::string tunables = environment("GLIBC_TUNABLES");
  if (hugePages && addressSpaceUnlimited() && tunables.find(kHugePageTunable) == std::string::npos) {
    const std::string added = std::string(kHugePageTunable) + "=1";
    setenv("GLIBC_TUNABLES", (tunables.empty() ? added : tunables + ":" + added).c_str(), 1);
    changed = true;
  }
  if (changed) execv("/proc/self/exe", argv);  // returns only on failure
}

void fitMallocToTheAddressSpace()
{
#if defined(__GLIBC__)
  if (!addressSpaceUnlimited()) mallopt(M_ARENA_MAX, kArenasUnderAnAddressSpaceLimit);
#endif
}

bool mallocAsksForHugePages()
{
  // name=value pairs separated by colons; glibc takes the last of a name.
  const std::string tunables = environment("GLIBC_TUNABLES");
  const std::string key = std::string(kHugePageTunable) + "=";
  bool asks = false;
  for (size_t begin = 0; begin <= tunables.size();) {
    const size_t end = std::min(tunables.find(':', begin), tunables.size());
    const std::string pair = tunables.substr(begin, end - begin);
    if (pair.rfind(key, 0) == 0) asks = pair.size() > key.size() && pair.substr(key.size()) != "0";
    begin = end + 1;
  }
  return asks;
}

}  // namespace lbmshape
