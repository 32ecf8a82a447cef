// Logs and progress go to stderr; stdout is reserved for --json results. A
// program that links the library may send them elsewhere (setSink).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace lbmshape::log {

enum class Level { Quiet = 0, Normal = 1, Verbose = 2 };

void setLevel(Level level);
Level level();

// What a message is, for a sink.
enum class Kind { Info, Verbose, Warning, Progress };
// Where the messages go instead of stderr: a plugin's log panel, a host's
// own logger. The sink gets each message alone, without stderr's
// "lbmshape: " and "warning: ", on the thread that logs it (a call's
// worker threads too), after the level has filtered it; a progress line
// comes as Kind::Progress (stderr rewrites it in place). It is called
// outside lbmshape's locks, so it may take the host's own (calls from
// several threads at once are the sink's to order), and must not throw; a
// message it logs itself goes to stderr. An empty function restores stderr.
// Warnings still reach the WarningCollector (a call's report) either way.
using Sink = std::function<void(Kind kind, const std::string& message)>;
void setSink(Sink sink);

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
