#include "core/passive_waiting.hpp"

#include <cstdlib>

#include <unistd.h>

namespace lbmshape {

void restartWithPassiveOpenMpWaiting(char** argv)
{
  if (std::getenv("OMP_WAIT_POLICY")) return;
  setenv("OMP_WAIT_POLICY", "passive", 1);
  execv("/proc/self/exe", argv);  // returns only on failure
}

}  // namespace lbmshape
