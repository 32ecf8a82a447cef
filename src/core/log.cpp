#include "lbmshape/core/log.hpp"

#include <atomic>
#include <iostream>
#include <mutex>
#include <unistd.h>

namespace lbmshape::log {
namespace {
std::atomic<Level> currentLevel{Level::Normal};
std::mutex streamMutex;         // whole lines from concurrent writer threads
bool progressOnScreen = false;  // a terminal progress line waits to be replaced (guarded by streamMutex)

// On a terminal a progress line is rewritten in place, and whatever is
// logged next replaces it; in a file every progress line stays.
bool stderrIsATerminal()
{
  static const bool terminal = isatty(STDERR_FILENO);
  return terminal;
}

void clearProgressLine()
{
  if (progressOnScreen) std::cerr << "\r\033[K";
  progressOnScreen = false;
}

void emit(const std::string& prefix, const std::string& message)
{
  std::lock_guard lock(streamMutex);
  clearProgressLine();
  std::cerr << prefix << message << '\n';
}
}  // namespace

void setLevel(Level l) { currentLevel = l; }
Level level() { return currentLevel; }

void info(const std::string& m)
{
  if (currentLevel >= Level::Normal) emit("lbmshape: ", m);
}
void verbose(const std::string& m)
{
  if (currentLevel >= Level::Verbose) emit("lbmshape: ", m);
}
namespace {
thread_local WarningCollector* innermostCollector = nullptr;
}

WarningCollector::WarningCollector() : outer_(innermostCollector) { innermostCollector = this; }
WarningCollector::~WarningCollector() { innermostCollector = outer_; }

void warning(const std::string& m)
{
  emit("lbmshape: warning: ", m);
  if (innermostCollector) innermostCollector->warnings_.push_back(m);
}

void progress(const std::string& m)
{
  if (currentLevel < Level::Normal) return;
  std::lock_guard lock(streamMutex);
  if (!stderrIsATerminal()) {
    std::cerr << "lbmshape: " << m << '\n';
    return;
  }
  std::cerr << "\rlbmshape: " << m << "\033[K" << std::flush;
  progressOnScreen = true;
}

void endProgress()
{
  std::lock_guard lock(streamMutex);
  clearProgressLine();
  std::cerr << std::flush;
}

}  // namespace lbmshape::log
