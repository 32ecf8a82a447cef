#include "core/log.hpp"

#include <atomic>
#include <iostream>
#include <mutex>

namespace lbmshape::log {
namespace {
std::atomic<Level> currentLevel{Level::Normal};
std::mutex streamMutex;  // whole lines from concurrent writer threads

void emit(const std::string& prefix, const std::string& message)
{
  std::lock_guard lock(streamMutex);
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
void warning(const std::string& m) { emit("lbmshape: warning: ", m); }

}  // namespace lbmshape::log
