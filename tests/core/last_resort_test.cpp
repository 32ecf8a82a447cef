#include "lbmshape/core/last_resort.hpp"

#include <atomic>
#include <new>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace lbmshape {
namespace {

// Threads of one parallel loop can run out of memory at the same moment:
// the process still ends with one line (on a 16-core host, compare under a
// tight `ulimit -v` printed "out of memory" twice) and exit code 5.
TEST(LastResortDeathTest, ThreadsThatFailAtOnceEndWithOneLine)
{
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  for (int trial = 0; trial < 5; ++trial)
    EXPECT_EXIT(
        {
          installLastResortHandler();
          constexpr int count = 8;
          std::atomic<int> ready{0};
          std::vector<std::thread> threads;
          for (int t = 0; t < count; ++t)
            threads.emplace_back([&ready] {
              ready.fetch_add(1);
              while (ready.load() < count) std::this_thread::yield();
              throw std::bad_alloc();  // escapes the thread: std::terminate
            });
          for (auto& t : threads) t.join();
        },
        ::testing::ExitedWithCode(5), "^lbmshape: error: out of memory\n$");
}

}  // namespace
}  // namespace lbmshape
