// main() of every test program: the environment every test runs in, set here
// rather than through CTest so that running a test binary by hand behaves the
// same as under ctest.
#include <cstdlib>

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
  // The Khronos validation layer on for every GPU test, and for every
  // lbmshape process a CLI test starts; any message fails the test.
  setenv("LBMSHAPE_VALIDATION", "1", 1);
  // Our own pipeline cache, so a developer's real cache is never touched.
  setenv("XDG_CACHE_HOME", LBMSHAPE_TEST_CACHE_HOME, 1);
  // Lavapipe's worker threads: one per core of these 2-core machines, unless
  // the caller chose otherwise.
  setenv("LP_NUM_THREADS", "2", 0);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
