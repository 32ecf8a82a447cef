// Freed heap memory goes back to the system when a stage asks
// (returnFreedHeapMemory), as the denoise does between the distances and
// the lattice.
#include <unistd.h>

#include <fstream>
#include <vector>

#include <gtest/gtest.h>

#include "lbmshape/core/address_sanitizer.hpp"
#include "lbmshape/core/host_memory.hpp"

namespace lbmshape {
namespace {

// Resident bytes of this process (/proc/self/statm's second field).
double residentBytes()
{
  std::ifstream statm("/proc/self/statm");
  double size = 0, resident = 0;
  statm >> size >> resident;
  return resident * double(sysconf(_SC_PAGESIZE));
}

TEST(HostMemory, FreedHeapMemoryGoesBackToTheSystem)
{
#if !defined(__GLIBC__)
  GTEST_SKIP() << "returnFreedHeapMemory() acts on glibc's allocator only";
#endif
  if (builtWithAddressSanitizer) GTEST_SKIP() << "AddressSanitizer's allocator keeps freed memory in quarantine";
  // A freed block of 30 MiB raises glibc's mmap threshold to its size, so
  // that blocks of 2 MiB then come from the heap, as a stage's arrays do
  // after an earlier stage freed its big ones.
  {
    std::vector<char>(30 << 20, 1);
  }
  constexpr size_t blockBytes = 2 << 20, blocks = 40;
  std::vector<std::vector<char>> arrays;
  for (size_t k = 0; k < blocks; ++k) arrays.emplace_back(blockBytes, char(k + 1));
  std::vector<char> last(blockBytes, 1);  // allocated last, kept: the heap's top stays in use
  arrays.clear();
  const double held = residentBytes();
  returnFreedHeapMemory();
  const double released = held - residentBytes();
  EXPECT_GT(released, 0.75 * double(blocks * blockBytes)) << "resident before: " << held;
  EXPECT_EQ(last[blockBytes - 1], 1);
}

}  // namespace
}  // namespace lbmshape
