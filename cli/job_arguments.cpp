#include "job_arguments.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "lbmshape/core/error.hpp"

namespace lbmshape::cli {
namespace {

namespace fs = std::filesystem;

// The positional arguments of each command, in order; they are paths.
const std::map<std::string, std::vector<std::string>> positionals = {
    {"denoise", {"input", "output"}},
    {"morph", {"source", "target", "output"}},
};

// Options whose value is a path: like the positionals, relative to the
// jobs file's folder.
bool takesPath(const std::string& key) { return key == "preview"; }

// CLI11 names the type an option converts its text to.
bool takesWholeNumber(const CLI::Option& o)
{
  return o.get_type_name().rfind("INT", 0) == 0 || o.get_type_name().rfind("UINT", 0) == 0;
}
bool takesNumber(const CLI::Option& o) { return takesWholeNumber(o) || o.get_type_name().rfind("FLOAT", 0) == 0; }
bool isFlag(const CLI::Option& o) { return o.get_expected_min() == 0; }

// A NUL in a job's string: no argument holds one, and a file name would end
// there, so that another file than the one named would be written.
void refuseNul(const std::string& text, const std::string& what)
{
  if (text.find('\0') != std::string::npos)
    throw UsageError(what + " holds a NUL character (\\u0000), which no path or argument may hold");
}

// The text of `value` for option `key`, or UsageError when its JSON type
// does not fit the option.
std::string optionText(const std::string& key, const nlohmann::json& value, const CLI::Option& option)
{
  const std::string quoted = "\"" + key + "\"";
  if (takesWholeNumber(option)) {
    // JSON writers may print whole numbers as 96.0; the value is what counts.
    if (!value.is_number() || value.get<double>() != std::floor(value.get<double>()))
      throw UsageError("option " + quoted + " must be a whole number, not " + value.dump());
    const bool unsignedOption = option.get_type_name().rfind("UINT", 0) == 0;
    const double lowest = unsignedOption ? 0.0 : -4294967295.0;
    // Beyond the widest option's values (a uint32 seed): an unsigned
    // option's own range, or far out of a signed one's (whose own check
    // would name it, but cannot be given a number this large).
    if (value.get<double>() < lowest || value.get<double>() > 4294967295.0)
      throw UsageError(unsignedOption
                           ? "option " + quoted + " must be a whole number from 0 to 4294967295, not " + value.dump()
                           : "option " + quoted + " is " + value.dump() + ", far beyond any value it takes");
    if (value.is_number_integer()) return value.dump();
    return std::to_string(static_cast<long long>(value.get<double>()));
  }
  if (takesNumber(option)) {
    if (value.is_number()) return value.dump();
    throw UsageError("option " + quoted + " must be a number, not " + value.dump());
  }
  if (value.is_string()) {
    // Empty, "--key=" would make the option take the next argument as its value.
    if (value.get<std::string>().empty())
      throw UsageError("option " + quoted + " is empty: give a value, or null (or leave it out) for the default");
    refuseNul(value.get<std::string>(), "option " + quoted);
    return value.get<std::string>();
  }
  throw UsageError("option " + quoted + " must be a string, not " + value.dump());
}

// A path of the jobs file, relative to its folder: "./-scan.obj" where the
// folder is the current one, so that a name starting with '-' is a path,
// never an option.
std::string jobPath(const fs::path& base, const fs::path& p)
{
  if (p.is_absolute()) return p.string();
  return ((base.empty() ? fs::path(".") : base) / p).string();
}

}  // namespace

std::vector<std::string> jobCommandLine(const nlohmann::json& job, const fs::path& base, const CLI::App& commands)
{
  if (!job.is_object()) throw UsageError("a job must be a JSON object, not " + job.dump());
  if (!job.contains("command") || !job["command"].is_string()) throw UsageError("a job needs a \"command\"");
  const std::string command = job["command"];
  auto known = positionals.find(command);
  if (known == positionals.end()) throw UsageError("unknown command \"" + command + "\" (use denoise or morph)");
  const CLI::App& definition = *commands.get_subcommand(command);

  std::vector<std::string> args = {command};
  for (const auto& name : known->second) {
    if (!job.contains(name) || !job[name].is_string())
      throw UsageError(command + " job needs \"" + name + "\" (a path)");
    if (job[name].get<std::string>().empty()) throw UsageError(command + " job's \"" + name + "\" is empty");
    refuseNul(job[name].get<std::string>(), command + " job's \"" + name + "\"");
    args.push_back(jobPath(base, job[name].get<std::string>()));
  }
  for (const auto& [key, value] : job.items()) {
    if (key == "command" || std::find(known->second.begin(), known->second.end(), key) != known->second.end()) continue;
    const CLI::Option* option = key == "help" ? nullptr : definition.get_option_no_throw("--" + key);
    if (!option)
      throw UsageError("unknown option \"" + key + "\" for " + command + " (see lbmshape " + command + " --help)");
    if (value.is_null()) continue;  // the default
    if (isFlag(*option)) {
      if (!value.is_boolean()) throw UsageError("option \"" + key + "\" is a flag: true or false, not " + value.dump());
      if (value.get<bool>()) args.push_back("--" + key);
    } else {
      // One argument, so that a value starting with '-' is never taken for an option.
      std::string text = optionText(key, value, *option);
      if (takesPath(key)) text = jobPath(base, text);
      args.push_back("--" + key + "=" + text);
    }
  }
  return args;
}

}  // namespace lbmshape::cli
