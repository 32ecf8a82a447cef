// Logs and progress go to stderr; stdout is reserved for --json results.
#pragma once

#include <string>
#include <vector>

namespace lbmshape::log {

enum class Level { Quiet = 0, Normal = 1, Verbose = 2 };

void setLevel(Level level);
Level level();

void info(const std::string& message);     // shown unless quiet
void verbose(const std::string& message);  // shown with --verbose
void warning(const std::string& message);  // always shown

// Collects the warnings logged on its thread while it lives, besides
// printing them, for a call's report ("warnings" in --json, and in the
// library's and Python's reports): a script that keeps --json and drops
// stderr still learns what its result lacks (a lost volume, parts that
// changed). Where collectors nest, the innermost collects. Warnings logged
// on other threads are printed only.
class WarningCollector {
public:
  WarningCollector();
  ~WarningCollector();
  WarningCollector(const WarningCollector&) = delete;
  WarningCollector& operator=(const WarningCollector&) = delete;

  const std::vector<std::string>& warnings() const { return warnings_; }

private:
  friend void warning(const std::string& message);
  std::vector<std::string> warnings_;
  WarningCollector* outer_;
};

// A progress line (see core/progress.hpp): rewritten in place on a terminal
// until endProgress() or the next message, one line each in a file.
void progress(const std::string& line);
void endProgress();

}  // namespace lbmshape::log
