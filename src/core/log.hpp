// Logs and progress go to stderr; stdout is reserved for --json results.
#pragma once

#include <string>

namespace lbmshape::log {

enum class Level { Quiet = 0, Normal = 1, Verbose = 2 };

void setLevel(Level level);
Level level();

void info(const std::string& message);     // shown unless quiet
void verbose(const std::string& message);  // shown with --verbose
void warning(const std::string& message);  // always shown

// A progress line (see core/progress.hpp): rewritten in place on a terminal
// until endProgress() or the next message, one line each in a file.
void progress(const std::string& line);
void endProgress();

}  // namespace lbmshape::log
