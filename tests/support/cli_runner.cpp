#include "support/cli_runner.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>
#include <unistd.h>

#include <gtest/gtest.h>

extern char** environ;

namespace lbmshape::testing {
namespace {

std::string shellQuote(const std::string& s)
{
  std::string quoted = "'";
  for (char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string slurp(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string lbmshapeBinary() { return LBMSHAPE_BINARY; }

namespace {

CliResult run(const std::string& prefix, const std::vector<std::string>& arguments)
{
  static int counter = 0;
  const auto base = std::filesystem::temp_directory_path() /
                    ("lbmshape-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::string command = prefix + shellQuote(LBMSHAPE_BINARY);
  for (const auto& a : arguments) command.append(" ").append(shellQuote(a));
  command += " >" + shellQuote(base.string() + ".out") + " 2>" + shellQuote(base.string() + ".err") + " </dev/null";
  const int status = std::system(command.c_str());
  CliResult result;
  // A signal that ends lbmshape reaches us as the shell's exit code 128 + N.
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = slurp(base.string() + ".out");
  result.err = slurp(base.string() + ".err");
  std::filesystem::remove(base.string() + ".out");
  std::filesystem::remove(base.string() + ".err");
  return result;
}

}  // namespace

CliResult runLbmshape(const std::vector<std::string>& arguments) { return run("", arguments); }

CliResult runLbmshapeWithin(size_t addressSpaceMegabytes, const std::vector<std::string>& arguments)
{
  return run("ulimit -v " + std::to_string(addressSpaceMegabytes * 1024) + " && ", arguments);
}

CliResult runLbmshapeWithFileSizeLimit(uintmax_t bytes, const std::vector<std::string>& arguments)
{
  return run("prlimit --fsize=" + std::to_string(bytes) + " ", arguments);
}

std::vector<std::string> nonEmptyLines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

std::vector<std::string> messageLines(const std::string& text)
{
  static const std::regex progress(R"(^lbmshape: [a-z ]+(\.\.\.|\s+[0-9]+% \(.*\),) [0-9]+\.[0-9] s$)");
  static const std::regex slowStage(R"(^lbmshape: [a-z_]+ +[0-9]+\.[0-9] ms( \(the device busy [0-9.]+ ms of it\))?$)");
  std::vector<std::string> lines = nonEmptyLines(text);
  std::erase_if(lines, [](const std::string& line) {
    return std::regex_match(line, progress) || std::regex_match(line, slowStage);
  });
  return lines;
}

pid_t spawnLbmshape(std::vector<std::string> arguments, const std::string& logFile, const std::string& outFile)
{
  arguments.insert(arguments.begin(), lbmshapeBinary());
  std::vector<char*> argv;
  for (auto& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, outFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int failed = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return failed ? -1 : pid;
}

int waitForExit(pid_t pid, std::chrono::milliseconds limit)
{
  const auto deadline = std::chrono::steady_clock::now() + limit;
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      ADD_FAILURE() << "still running after " << limit.count() << " ms";
      return status;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return status;
}

bool waitForFile(const std::filesystem::path& file, std::chrono::milliseconds limit)
{
  const auto deadline = std::chrono::steady_clock::now() + limit;
  while (!std::filesystem::exists(file) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return std::filesystem::exists(file);
}

}  // namespace lbmshape::testing
