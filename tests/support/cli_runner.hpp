// Runs the lbmshape binary as a user would, for end-to-end tests of the
// command line: exit code, stdout and stderr.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "lbmshape/core/address_sanitizer.hpp"

namespace lbmshape::testing {

struct CliResult {
  int exitCode = -1;  // 128 + N when lbmshape died of signal N
  std::string out;    // stdout
  std::string err;    // stderr
};

CliResult runLbmshape(const std::vector<std::string>& arguments);

// The same under an address-space limit (ulimit -v), as on a machine with
// that much memory: for the tests of failing well when memory runs out.
CliResult runLbmshapeWithin(size_t addressSpaceMegabytes, const std::vector<std::string>& arguments);

// The same under a file-size limit (prlimit --fsize, in bytes; the shell's
// ulimit -f counts in units that differ between shells), as on a disk that
// fills: for the tests of writes that fail part way.
CliResult runLbmshapeWithFileSizeLimit(uintmax_t bytes, const std::vector<std::string>& arguments);

// False in a build with AddressSanitizer, which reserves terabytes of
// address space for its shadow memory up front: no lbmshape of that build
// starts under an address-space limit, so the tests that use one skip.
constexpr bool addressSpaceLimitsWork() { return !builtWithAddressSanitizer; }
#define LBMSHAPE_SKIP_WITHOUT_ADDRESS_SPACE_LIMITS()  \
  if (!::lbmshape::testing::addressSpaceLimitsWork()) \
  GTEST_SKIP() << "AddressSanitizer reserves its shadow memory as address space: ulimit -v cannot apply here"

// lbmshape started in the background, its stderr sent to `logFile` and its
// stdout to `outFile` (each /dev/null unless given), for the tests that
// signal it; -1 if it did not start.
pid_t spawnLbmshape(std::vector<std::string> arguments, const std::string& logFile = "/dev/null",
                    const std::string& outFile = "/dev/null");

// The wait status of `pid`; a test failure, and the process killed, if it
// still runs after `limit` (a failing test must not hang).
int waitForExit(pid_t pid, std::chrono::milliseconds limit);

// Waits until `file` exists (a spawned lbmshape has written that far), at
// most `limit`; whether it exists.
bool waitForFile(const std::filesystem::path& file, std::chrono::milliseconds limit);

// Path of the lbmshape binary under test.
std::string lbmshapeBinary();

// Lines of text, without empty ones.
std::vector<std::string> nonEmptyLines(const std::string& text);
// The same without progress lines ("lbmshape: sdf  42% (part), 1.0 s"),
// which a stage prints once it has run for a second, and the time of a stage
// that took over a second ("lbmshape: sdf  4012.3 ms"): on a busy machine
// they come before an error too, and are not part of what it says.
std::vector<std::string> messageLines(const std::string& text);

}  // namespace lbmshape::testing
