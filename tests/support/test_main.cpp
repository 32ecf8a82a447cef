// main() of every test program: the environment every test runs in, set here
// rather than through CTest so that running a test binary by hand behaves the
// same as under ctest.
#include <cstdlib>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

int main(int argc, char** argv)
{
  // OpenMP's idle threads wait by spinning (libgomp's default), and ctest -j2
  // runs two tests on two cores, so each test's spinning takes the core the
  // other needs: with passive waiting the release suite takes 168 s instead
  // of 240 s. libgomp reads the variable as it loads, before main, so the
  // program starts itself again with it set (where that fails, it goes on,
  // only slower). It changes no result, only how threads wait.
  if (!std::getenv("OMP_WAIT_POLICY")) {
    setenv("OMP_WAIT_POLICY", "passive", 1);
    execv("/proc/self/exe", argv);
  }
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
