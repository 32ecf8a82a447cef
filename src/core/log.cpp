#include "lbmshape/core/log.hpp"

#include <atomic>
#include <iostream>
#include <memory>
#include <mutex>
#include <unistd.h>
#include <utility>

namespace lbmshape::log {
namespace {
std::atomic<Level> currentLevel{Level::Normal};
std::mutex streamMutex;         // whole lines from concurrent writer threads
bool progressOnScreen = false;  // a terminal progress line waits to be replaced (guarded by streamMutex)
std::mutex sinkMutex;
std::shared_ptr<const Sink> currentSink;  // guarded by sinkMutex; null: stderr
thread_local bool inSink = false;         // a message the sink logs goes to stderr

// The program's sink, if it set one and this thread is not already in it.
std::shared_ptr<const Sink> sink()
{
  if (inSink) return nullptr;
  std::lock_guard lock(sinkMutex);
  return currentSink;
}

// Hands the message to `to`, outside every lock of this file; true when
// it did.
bool sendTo(const std::shared_ptr<const Sink>& to, Kind kind, const std::string& message)
{
  if (!to) return false;
  inSink = true;
  try {
    (*to)(kind, message);
  } catch (...) {
    // A sink must not throw; a message lost is better than a call that
    // fails in the middle of its work for a log line.
  }
  inSink = false;
  return true;
}

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

void setSink(Sink s)
{
  std::shared_ptr<const Sink> replaced;  // let go outside the lock: its end may wait (for Python's GIL)
  std::lock_guard lock(sinkMutex);
  replaced = std::exchange(currentSink, s ? std::make_shared<const Sink>(std::move(s)) : nullptr);
}

void info(const std::string& m)
{
  if (currentLevel >= Level::Normal && !sendTo(sink(), Kind::Info, m)) emit("lbmshape: ", m);
}
void verbose(const std::string& m)
{
  if (currentLevel >= Level::Verbose && !sendTo(sink(), Kind::Verbose, m)) emit("lbmshape: ", m);
}
namespace {
thread_local WarningCollector* innermostCollector = nullptr;
}

WarningCollector::WarningCollector() : outer_(innermostCollector) { innermostCollector = this; }
WarningCollector::~WarningCollector() { innermostCollector = outer_; }

void warning(const std::string& m)
{
  if (!sendTo(sink(), Kind::Warning, m)) emit("lbmshape: warning: ", m);
  if (innermostCollector) innermostCollector->warnings_.push_back(m);
}

void progress(const std::string& m)
{
  if (currentLevel < Level::Normal) return;
  if (sendTo(sink(), Kind::Progress, m)) return;
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
