#include "core/interrupt.hpp"

#include <atomic>
#include <csignal>

#include "core/error.hpp"

namespace lbmshape::interrupt {
namespace {
std::atomic<bool> flag{false};

extern "C" void onInterrupt(int)
{
  flag = true;
  std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C is not ignored
}
}  // namespace

void installHandler() { std::signal(SIGINT, onInterrupt); }
bool requested() { return flag; }

void check(const std::string& whatWasDone)
{
  if (flag) throw Interrupted("interrupted: " + whatWasDone);
}

}  // namespace lbmshape::interrupt
