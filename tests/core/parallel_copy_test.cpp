#include "lbmshape/core/parallel_copy.hpp"

#include <numeric>
#include <vector>

#include <gtest/gtest.h>

namespace lbmshape {
namespace {

// A copy split among the threads, of sizes below, at and across its chunk.
TEST(ParallelCopy, CopiesEveryByteOfAnySize)
{
  for (size_t bytes : {size_t(0), size_t(1), size_t(1) << 20, (size_t(5) << 20) + 3}) {
    std::vector<unsigned char> from(bytes), to(bytes, 0);
    std::iota(from.begin(), from.end(), 1);
    parallelCopy(to.data(), from.data(), bytes);
    EXPECT_EQ(to, from) << bytes << " bytes";
  }
}

}  // namespace
}  // namespace lbmshape
