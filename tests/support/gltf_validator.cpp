#include "support/gltf_validator.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

extern char** environ;

namespace lbmshape::testing {
namespace {

// Runs `argv` and returns what it printed on stdout (its stderr goes to the
// test's), and its exit status through `status`; a failure to start is
// reported through `failure`.
std::string runCapturingStdout(std::vector<std::string> argv, int& status, std::string& failure)
{
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    failure = std::string("pipe: ") + std::strerror(errno);
    return {};
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  std::vector<char*> args;
  for (auto& a : argv) args.push_back(a.data());
  args.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  std::string output;
  if (spawned == 0) {
    char buffer[65536];
    for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) != 0;) {
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) break;
      output.append(buffer, size_t(n));
    }
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  } else {
    failure = "cannot run " + argv[0] + ": " + std::strerror(spawned);
  }
  ::close(fds[0]);
  return output;
}

}  // namespace

ThreeJsLoad loadWithThreeJs(const std::filesystem::path& file)
{
  ThreeJsLoad result;
  const std::filesystem::path script =
      std::filesystem::path(LBMSHAPE_GLTF_VALIDATOR_SCRIPT).parent_path() / "three_load.mjs";
  if (!std::filesystem::exists(script.parent_path() / "node_modules" / "three")) {
    result.failure =
        "three.js is not installed (install it with: npm ci --prefix " + script.parent_path().string() + ")";
    return result;
  }
  int status = 0;
  const std::string output =
      runCapturingStdout({LBMSHAPE_NODE_EXECUTABLE, script.string(), file.string()}, status, result.failure);
  if (!result.failure.empty()) return result;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    result.failure = "three.js could not load " + file.string() + " (see its message above)";
    return result;
  }
  try {
    result.scene = nlohmann::json::parse(output);
  } catch (const std::exception& e) {
    result.failure = std::string("three_load.mjs printed no JSON: ") + e.what();
  }
  return result;
}

GltfValidation validateGltf(const std::filesystem::path& file)
{
  GltfValidation result;
  const std::filesystem::path script = LBMSHAPE_GLTF_VALIDATOR_SCRIPT;
  const std::string install = " (install it with: npm ci --prefix " + script.parent_path().string() +
                              "; Node comes with scripts/install-deps.sh --with-test-tools)";
  if (!std::filesystem::exists(script.parent_path() / "node_modules" / "gltf-validator")) {
    result.failure = "the glTF-Validator is not installed" + install;
    return result;
  }
  int status = 0;
  const std::string output =
      runCapturingStdout({LBMSHAPE_NODE_EXECUTABLE, script.string(), file.string()}, status, result.failure);
  if (!result.failure.empty()) {
    result.failure += install;
    return result;
  }
  // validate.mjs exits 1 when it found errors or warnings, which the counts
  // below say; anything else but 0 means it could not judge the file.
  if (!WIFEXITED(status) || (WEXITSTATUS(status) != 0 && WEXITSTATUS(status) != 1)) {
    result.failure = "the glTF-Validator could not validate " + file.string() + " (see its message above)";
    return result;
  }
  try {
    const auto report = nlohmann::json::parse(output);
    result.errors = report.at("errors").get<int>();
    result.warnings = report.at("warnings").get<int>();
    result.infos = report.at("infos").get<int>();
    result.hints = report.at("hints").get<int>();
    for (const auto& m : report.at("messages"))
      result.messages.push_back(m.at("severity").get<std::string>() + " " + m.at("code").get<std::string>() + " at " +
                                m.at("pointer").get<std::string>() + ": " + m.at("message").get<std::string>());
  } catch (const nlohmann::json::exception& e) {
    result.failure = std::string("unexpected output from validate.mjs: ") + e.what();
  }
  return result;
}

std::ostream& operator<<(std::ostream& out, const GltfValidation& v)
{
  if (!v.failure.empty()) return out << v.failure;
  out << v.errors << " errors, " << v.warnings << " warnings, " << v.infos << " infos, " << v.hints << " hints";
  for (const auto& m : v.messages) out << "\n  " << m;
  return out;
}

}  // namespace lbmshape::testing
