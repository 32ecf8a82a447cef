// main() of every test program: the environment every test runs in, set here
// rather than through CTest so that running a test binary by hand behaves the
// same as under ctest.
#include <cstdlib>
#include <string>

#include "lbmshape/core/process_settings.hpp"

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
  // OpenMP's idle threads wait passively, as in lbmshape itself: ctest -j2
  // runs two tests on two cores, and each one's spinning took the core the
  // other needed (core/process_settings.hpp). It changes no result. Huge
  // pages are left to the lbmshape processes the tests start (they inherit
  // this environment, and under an address-space limit go without).
  lbmshape::restartWithProcessSettings(argv, false);
  // The Khronos validation layer on for every GPU test, and for every
  // lbmshape process a CLI test starts; any message fails the test.
  setenv("LBMSHAPE_VALIDATION", "1", 1);
  // Our own pipeline cache, so a developer's real cache is never touched.
  setenv("XDG_CACHE_HOME", LBMSHAPE_TEST_CACHE_HOME, 1);
  // Lavapipe's worker threads: one per core of these 2-core machines, unless
  // the caller chose otherwise.
  setenv("LP_NUM_THREADS", "2", 0);
  // Tests labelled unit use no device: CTest runs them with
  // LBMSHAPE_TEST_WITHOUT_DEVICE=1, and the Vulkan loader then finds no
  // driver (VK_DRIVER_FILES; VK_ICD_FILENAMES for loaders before 1.3.207;
  // nothing added by VK_ADD_DRIVER_FILES), so a test that reaches for a
  // device fails instead of passing under the wrong label.
  if (const char* without = std::getenv("LBMSHAPE_TEST_WITHOUT_DEVICE"); without && std::string(without) == "1") {
    const char* none = "/nonexistent/lbmshape-unit-tests-use-no-vulkan-driver.json";
    setenv("VK_DRIVER_FILES", none, 1);
    setenv("VK_ICD_FILENAMES", none, 1);
    unsetenv("VK_ADD_DRIVER_FILES");
  }
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
