#include "run_command.hpp"

#include <algorithm>
#include <charconv>
#include <map>
#include <set>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <vulkan/vulkan.hpp>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/log.hpp"
#include "lbmshape/core/mapped_file.hpp"
#include "job_arguments.hpp"
#include "job_files.hpp"
#include "mesh_commands.hpp"
#include "usage_messages.hpp"

namespace lbmshape::cli {
namespace {
namespace fs = std::filesystem;

struct RunArguments {
  std::string jobsFile;
  bool failFast = false;
  bool checkOnly = false;  // --check: every job's options checked, none run
  std::string shard;       // "K/N": only jobs K, K + N, K + 2N, ... (numbered from 1)
};

// One of N parts of a jobs file, for running it on N machines or processes
// (GNU parallel, a Slurm array: docs/scaling.md): part K holds jobs K, K + N,
// K + 2N, ..., so that every job is in exactly one part.
struct Shard {
  size_t part = 1, parts = 1;
  bool holds(size_t jobNumber) const { return (jobNumber - 1) % parts == part - 1; }
};

Shard parseShard(const std::string& text)
{
  // K and N as whole numbers, nothing else around them.
  const char* const first = text.data();
  const char* const last = first + text.size();
  long part = 0, parts = 0;
  const auto k = std::from_chars(first, last, part);
  const bool wellFormed = k.ec == std::errc() && k.ptr != last && *k.ptr == '/' && [&] {
    const auto n = std::from_chars(k.ptr + 1, last, parts);
    return n.ec == std::errc() && n.ptr == last;
  }();
  if (!wellFormed || parts < 1 || parts > 1000000 || part < 1 || part > parts)
    throw UsageError("--shard must be K/N with 1 <= K <= N <= 1000000 (part K of N, e.g. 2/4), not '" + text + "'");
  return {size_t(part), size_t(parts)};
}

// A jobs file is an array of flat objects: nesting beyond this is no jobs
// file, and nesting without bound would overflow the stack in nlohmann's
// recursive destructor and serializer.
constexpr int maxJobsFileDepth = 16;
struct TooDeep {};

struct DuplicateKey {
  size_t job;
  std::string key;
};

// Reads a jobs file's JSON as events, before it is parsed into values: a
// key given twice in one object (JSON would keep the last silently), and
// nesting deeper than any jobs file needs, which the parse could not
// survive. A SAX pass of its own: the parser's callback hook (which did this
// before) walked the whole array at the end of every job, so 200,000 jobs
// took 15 s.
class JobsFileCheck : public nlohmann::json_sax<nlohmann::json> {
public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override
  {
    enter();
    if (open_ == 2 && arrays_ == 1) ++jobsSeen_;  // an object in the top-level array: a job
    keys_.emplace_back();
    return true;
  }
  bool key(string_t& key) override
  {
    if (!keys_.back().insert(key).second) throw DuplicateKey{jobsSeen_, key};
    return true;
  }
  bool end_object() override
  {
    keys_.pop_back();
    --open_;
    return true;
  }
  bool start_array(std::size_t) override
  {
    enter();
    ++arrays_;
    return true;
  }
  bool end_array() override
  {
    --arrays_;
    --open_;
    return true;
  }
  // The parse that follows says what is wrong, as it always did.
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

private:
  void enter()
  {
    if (open_ >= size_t(maxJobsFileDepth)) throw TooDeep{};
    ++open_;
  }
  size_t open_ = 0, arrays_ = 0, jobsSeen_ = 0;
  std::vector<std::set<std::string>> keys_;
};

// The jobs of `file`. A key given twice in one job is refused, naming the
// job and the key (the jobs' files are compared by checkJobFiles).
nlohmann::json readJobs(const fs::path& file)
{
  const MappedFile text(file);  // a regular file, or an InputError that says what it is
  nlohmann::json jobs;
  try {
    JobsFileCheck check;
    nlohmann::json::sax_parse(text.bytes(), &check);
    jobs = nlohmann::json::parse(text.bytes());  // where the check met a parse error, throws it, with its place
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError("cannot read " + file.string() + ": not valid JSON (" + e.what() + ")");
  } catch (const nlohmann::json::out_of_range& e) {  // a number beyond a double's range
    throw InputError("cannot read " + file.string() + ": a number out of range (" + e.what() + ")");
  } catch (const TooDeep&) {
    throw InputError("cannot read " + file.string() + ": its JSON nests more than " + std::to_string(maxJobsFileDepth) +
                     " levels deep (a jobs file is an array of objects of options)");
  } catch (const DuplicateKey& d) {
    throw UsageError(file.string() + ": job " + std::to_string(d.job) + " gives \"" + d.key + "\" twice");
  }
  if (!jobs.is_array()) throw InputError("cannot read " + file.string() + ": expected a JSON array of jobs");
  return jobs;
}

// The command and its paths (a morph's output folder too), to name a job in the log.
std::string describe(const std::vector<std::string>& args)
{
  const size_t paths = !args.empty() && args[0] == "morph" ? 3 : 2;
  std::string s;
  for (size_t i = 0; i < args.size() && i <= paths; ++i) s += (i ? " " : "") + args[i];
  return s;
}

// Parses one job through the same command definitions as the command
// line, which runs it, or with `checkOnly` only checks its options; `what`
// gets the job's command and paths, for the log.
nlohmann::json parseJob(const nlohmann::json& job, const fs::path& base, const CommonOptions& common, bool checkOnly,
                        std::string& what)
{
  CommonOptions jobOptions = common;  // shares the opened device
  nlohmann::json report;
  jobOptions.json = true;  // the job's own output stays quiet; its report is collected
  jobOptions.report = [&report](const nlohmann::json& r) { report = r; };
  jobOptions.checkOnly = checkOnly;
  CLI::App app("job");
  app.require_subcommand(1);
  // Only the job's own command is defined: defining both took half of the
  // time a jobs file's first pass spends on each job.
  const bool named = job.is_object() && job.contains("command") && job["command"].is_string();
  const std::string command = named ? job["command"].get<std::string>() : std::string();
  if (command != "morph") addDenoiseCommand(app, jobOptions);
  if (command != "denoise") addMorphCommand(app, jobOptions);
  const std::vector<std::string> args = jobCommandLine(job, base, app);
  what += " (" + describe(args) + ")";
  if (!checkOnly) log::info(what + "...");
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw UsageError(plainParseError(app, e));
  }
  return report;
}

bool isUsageError(const std::exception& e)
{
  auto* error = dynamic_cast<const Error*>(&e);
  return dynamic_cast<const CLI::ParseError*>(&e) || (error && error->code() == ExitCode::Usage);
}

// The jobs of the run whose options are wrong (an unknown key, a value of
// the wrong type or out of range, a missing path), each with its message,
// found before any job runs: a mistake in job 500 used to surface only
// after the hours that jobs 1 to 499 took. What needs the meshes (a file
// missing, a shape that encloses nothing) is found when the job runs.
std::map<size_t, std::string> jobsWithUsageErrors(const nlohmann::json& jobs, const fs::path& base,
                                                  const CommonOptions& common, const Shard& shard)
{
  // On all cores: defining a command's options for CLI11 takes about 40 us
  // a job, 8 s on one core for 200,000 jobs. The checks log nothing.
  std::vector<std::string> messages(jobs.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (size_t i = 0; i < jobs.size(); ++i) {
    if (!shard.holds(i + 1)) continue;
    std::string what = "job " + std::to_string(i + 1);
    try {
      parseJob(jobs[i], base, common, true, what);
    } catch (const std::exception& e) {
      if (isUsageError(e)) messages[i] = what + ": " + e.what();
    }
  }
  std::map<size_t, std::string> wrong;
  for (size_t i = 0; i < jobs.size(); ++i)
    if (!messages[i].empty()) wrong.emplace(i, std::move(messages[i]));
  return wrong;
}

// A job's entry in the results: its number, and its command where it names one.
nlohmann::json resultOf(const nlohmann::json& jobs, size_t index)
{
  nlohmann::json result = {{"job", index + 1}};
  if (jobs[index].is_object() && jobs[index].contains("command") && jobs[index]["command"].is_string())
    result["command"] = jobs[index]["command"];
  return result;
}

// The entry of a job whose options are wrong, from its message.
nlohmann::json failureOf(const nlohmann::json& jobs, size_t index, const std::string& message)
{
  nlohmann::json result = resultOf(jobs, index);
  result.update({{"ok", false}, {"exit_code", int(ExitCode::Usage)}, {"error", message}});
  return result;
}

// The report of `run --json`, whichever way the run ends.
nlohmann::json runReport(const RunArguments& a, const nlohmann::json& jobs, size_t run, size_t failed, bool interrupted,
                         const nlohmann::json& results)
{
  return {{"command", "run"},
          {"jobs", jobs.size()},
          {"run", run},
          {"failed", failed},
          {"interrupted", interrupted},
          {"shard", a.shard.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.shard)},
          {"results", results}};
}

// `run --check`: every job of the run checked, none run. Its report lists
// each job, "ok" or with its error; a wrong job is a usage error (exit 2).
void reportCheck(const CommonOptions& common, const RunArguments& a, const nlohmann::json& jobs, const Shard& shard,
                 const std::map<size_t, std::string>& wrong, size_t jobsInPart)
{
  nlohmann::json results = nlohmann::json::array();
  for (size_t i = 0; i < jobs.size(); ++i) {
    if (!shard.holds(i + 1)) continue;
    auto found = wrong.find(i);
    if (found != wrong.end()) {
      results.push_back(failureOf(jobs, i, found->second));
      log::warning(found->second);
    } else {
      nlohmann::json result = resultOf(jobs, i);
      result["ok"] = true;
      results.push_back(result);
    }
  }
  nlohmann::json report = runReport(a, jobs, 0, wrong.size(), false, results);
  report["check"] = true;
  common.report(report);
  if (!wrong.empty())
    throw UsageError(std::to_string(wrong.size()) + " of " + std::to_string(jobsInPart) +
                     " jobs have wrong options; first: " + wrong.begin()->second);
  log::info("the options of all " + std::to_string(jobsInPart) + " jobs" +
            (a.shard.empty() ? "" : " of part " + a.shard) + " are right; no job was run (--check)");
}

void runJobs(CommonOptions& common, const RunArguments& a)
{
  const Shard shard = a.shard.empty() ? Shard{} : parseShard(a.shard);
  const fs::path file = a.jobsFile;
  const nlohmann::json jobs = readJobs(file);
  const fs::path base = file.parent_path();
  size_t jobsInPart = 0;
  for (size_t i = 0; i < jobs.size(); ++i) jobsInPart += shard.holds(i + 1);
  checkJobFiles(
      jobs, file, [&shard](size_t job) { return shard.holds(job); }, !a.shard.empty());
  const std::map<size_t, std::string> wrong = jobsWithUsageErrors(jobs, base, common, shard);
  if (a.checkOnly) return reportCheck(common, a, jobs, shard, wrong, jobsInPart);
  if (!wrong.empty()) {
    const std::string count = std::to_string(wrong.size()) + " of " + std::to_string(jobsInPart) + " jobs";
    if (a.failFast) {
      const auto& [index, message] = *wrong.begin();
      // No job ran (as --check reports it); the wrong one is the failure.
      common.report(runReport(a, jobs, 0, 1, false, nlohmann::json::array({failureOf(jobs, index, message)})));
      throw UsageError(count + " have wrong options, found before any job ran (--fail-fast); first: " + message);
    }
    log::warning(count + " have wrong options and will fail when their turn comes; first: " + wrong.begin()->second);
  }
  common.computeDevice();  // opened once, before the jobs copy the options
  nlohmann::json results = nlohmann::json::array();
  int failed = 0, firstFailureCode = 0;
  std::string firstFailure;
  // The report, also of a run stopped by a signal: the jobs done, and the
  // one that was stopped, so that a script can run the rest.
  const auto report = [&](bool interrupted) {
    common.report(runReport(a, jobs, results.size(), size_t(failed), interrupted, results));
  };
  const auto jobsDone = [&] {
    return std::to_string(results.size()) + " of " + std::to_string(jobsInPart) + " jobs done";
  };
  for (size_t i = 0; i < jobs.size(); ++i) {
    if (!shard.holds(i + 1)) continue;
    nlohmann::json result = resultOf(jobs, i);
    std::string what = "job " + std::to_string(i + 1);
    try {
      interrupt::check(jobsDone());
    } catch (const Interrupted&) {
      report(true);
      throw;
    }
    try {
      result["report"] = parseJob(jobs[i], base, common, false, what);
      result["ok"] = true;
    } catch (const Interrupted& e) {
      ++failed;  // its outputs are not all there: a failure, like any other
      result["ok"] = false;
      result["exit_code"] = int(e.code());
      result["error"] = e.what();
      const std::string done = jobsDone();
      results.push_back(result);
      report(true);
      throw Interrupted(std::string(e.what()) + "; " + done, e.signal());
    } catch (const std::exception& e) {
      int code = int(ExitCode::Device);
      if (auto* error = dynamic_cast<const Error*>(&e))
        code = int(error->code());
      else if (dynamic_cast<const CLI::ParseError*>(&e))
        code = int(ExitCode::Usage);
      result["ok"] = false;
      result["exit_code"] = code;
      result["error"] = e.what();
      log::warning(what + " failed: " + e.what());
      if (failed++ == 0) firstFailureCode = code, firstFailure = what + ": " + e.what();
    }
    results.push_back(result);
    if (failed && a.failFast) break;
  }
  report(false);
  if (failed)
    throw Error(ExitCode(firstFailureCode),
                std::to_string(failed) + " of " + std::to_string(results.size()) + " jobs failed" +
                    (a.failFast ? " (stopped at the first, --fail-fast)" : "") + "; first: " + firstFailure);
  if (results.empty())
    log::info(jobs.empty() ? file.string() + " holds no jobs" : "part " + a.shard + " holds no jobs");
  else
    log::info("all " + std::to_string(results.size()) + " jobs" + (a.shard.empty() ? "" : " of part " + a.shard) +
              " succeeded");
}

}  // namespace

void addRunCommand(CLI::App& app, CommonOptions& common)
{
  auto a = std::make_shared<RunArguments>();
  auto* cmd = app.add_subcommand("run", "Run a JSON list of denoise and morph jobs in one process");
  cmd->add_option("jobs", a->jobsFile, "Jobs file: a JSON array of {\"command\": ..., paths, options}")->required();
  cmd->add_flag("--fail-fast", a->failFast,
                "Stop at the first job that fails (before any job runs, where a job's options are wrong)");
  cmd->add_flag("--check", a->checkOnly, "Check every job's options and run none: exit 0, or 2 naming each wrong job");
  cmd->add_option("--shard", a->shard,
                  "Run only part K of N of the jobs (K/N: jobs K, K+N, K+2N, ...), one part per machine or process");
  cmd->callback([&common, a] { runJobs(common, *a); });
}

}  // namespace lbmshape::cli
