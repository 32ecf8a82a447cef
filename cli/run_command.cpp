#include "run_command.hpp"

#include <algorithm>
#include <charconv>
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
#include "mesh_commands.hpp"

namespace lbmshape::cli {
namespace {
namespace fs = std::filesystem;

struct RunArguments {
  std::string jobsFile;
  bool failFast = false;
  std::string shard;  // "K/N": only jobs K, K + N, K + 2N, ... (numbered from 1)
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

// What a job writes: its output (a file, or a morph's folder) and its
// preview picture, each as an absolute path without a trailing separator.
struct JobWrite {
  fs::path path;
  size_t job;        // 1-based
  std::string text;  // as the jobs file gives it
  bool folder;       // a morph's folder of frames
};

std::vector<JobWrite> writesOf(const nlohmann::json& jobs, const fs::path& file)
{
  std::vector<JobWrite> writes;
  for (size_t i = 0; i < jobs.size(); ++i) {
    if (!jobs[i].is_object()) continue;
    const bool morph = jobs[i].contains("command") && jobs[i]["command"] == "morph";
    for (const char* key : {"output", "preview"}) {
      if (!jobs[i].contains(key) || !jobs[i][key].is_string()) continue;
      std::error_code ec;
      const fs::path given = fs::absolute(file.parent_path() / jobs[i][key].get<std::string>(), ec);
      fs::path path = fs::weakly_canonical(given, ec);
      if (ec) path = given.lexically_normal();
      if (path.has_relative_path() && path.filename().empty()) path = path.parent_path();  // "frames/" is "frames"
      writes.push_back({path, i + 1, jobs[i][key].get<std::string>(), morph && std::string(key) == "output"});
    }
  }
  return writes;
}

// Whether `inner` lies inside folder `outer`.
bool inside(const fs::path& inner, const fs::path& outer)
{
  const auto [o, i] = std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end());
  return o == outer.end() && i != inner.end();
}

// Two jobs writing the same file (the second would replace the first's
// result), however its path is spelled, or one writing into another's
// folder of frames, are refused, naming both jobs. Sorted by path, so a
// jobs file of 200,000 jobs is checked in a moment (pair by pair it took
// minutes): equal paths lie side by side, and what lies inside a folder
// comes right after it, paths comparing component by component.
void requireDistinctOutputs(const nlohmann::json& jobs, const fs::path& file)
{
  std::vector<JobWrite> writes = writesOf(jobs, file);
  // Sorted as strings whose separator sorts before every other character:
  // the order of comparing component by component, at a string compare's
  // cost (path's own operator< took 19 s for 200,000 jobs).
  std::vector<std::pair<std::string, size_t>> keys(writes.size());
  for (size_t w = 0; w < writes.size(); ++w) {
    keys[w] = {writes[w].path.generic_string(), w};
    std::replace(keys[w].first.begin(), keys[w].first.end(), '/', '\x01');
  }
  std::sort(keys.begin(), keys.end());
  std::vector<JobWrite> sorted;
  sorted.reserve(writes.size());
  for (const auto& [key, w] : keys) sorted.push_back(std::move(writes[w]));
  writes = std::move(sorted);
  for (size_t a = 0; a + 1 < writes.size(); ++a)
    for (size_t b = a + 1; b < writes.size() && writes[b].path == writes[a].path; ++b)
      if (writes[b].job != writes[a].job)
        throw UsageError(file.string() + ": jobs " + std::to_string(std::min(writes[a].job, writes[b].job)) + " and " +
                         std::to_string(std::max(writes[a].job, writes[b].job)) + " both write " + writes[b].text);
  for (size_t a = 0; a < writes.size(); ++a) {
    const JobWrite& folder = writes[a];
    if (!folder.folder) continue;
    for (size_t b = a + 1; b < writes.size() && (writes[b].path == folder.path || inside(writes[b].path, folder.path));
         ++b)
      if (writes[b].job != folder.job && writes[b].path != folder.path)
        throw UsageError(file.string() + ": job " + std::to_string(writes[b].job) + " writes " + writes[b].text +
                         " into job " + std::to_string(folder.job) + "'s folder of frames " + folder.text);
  }
}

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

// The jobs of `file`. A key given twice in one job and jobs whose outputs
// clash (requireDistinctOutputs) are refused, naming the jobs and the key.
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
  requireDistinctOutputs(jobs, file);
  return jobs;
}

// The command and the first paths, to name a job in the log.
std::string describe(const std::vector<std::string>& args)
{
  std::string s;
  for (size_t i = 0; i < args.size() && i < 3; ++i) s += (i ? " " : "") + args[i];
  return s;
}

// Runs one job through the same command definitions as the command line;
// `what` gets the job's command and paths, for the log.
nlohmann::json runJob(const nlohmann::json& job, const fs::path& base, const CommonOptions& common, std::string& what)
{
  CommonOptions jobOptions = common;  // shares the opened device
  nlohmann::json report;
  jobOptions.json = true;  // the job's own output stays quiet; its report is collected
  jobOptions.report = [&report](const nlohmann::json& r) { report = r; };
  CLI::App app("job");
  app.require_subcommand(1);
  addDenoiseCommand(app, jobOptions);
  addMorphCommand(app, jobOptions);
  const std::vector<std::string> args = jobCommandLine(job, base, app);
  what += " (" + describe(args) + ")";
  log::info(what + "...");
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  app.parse(reversed);
  return report;
}

void runJobs(CommonOptions& common, const RunArguments& a)
{
  const Shard shard = a.shard.empty() ? Shard{} : parseShard(a.shard);
  const fs::path file = a.jobsFile;
  const nlohmann::json jobs = readJobs(file);
  const fs::path base = file.parent_path();
  common.computeDevice();  // opened once, before the jobs copy the options
  nlohmann::json results = nlohmann::json::array();
  int failed = 0, firstFailureCode = 0;
  std::string firstFailure;
  size_t jobsInPart = 0;
  for (size_t i = 0; i < jobs.size(); ++i) jobsInPart += shard.holds(i + 1);
  // The report, also of a run stopped by a signal: the jobs done, and the
  // one that was stopped, so that a script can run the rest.
  const auto report = [&](bool interrupted) {
    common.report({{"command", "run"},
                   {"jobs", jobs.size()},
                   {"run", results.size()},
                   {"failed", failed},
                   {"interrupted", interrupted},
                   {"shard", a.shard.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.shard)},
                   {"results", results}});
  };
  const auto jobsDone = [&] {
    return std::to_string(results.size()) + " of " + std::to_string(jobsInPart) + " jobs done";
  };
  for (size_t i = 0; i < jobs.size(); ++i) {
    if (!shard.holds(i + 1)) continue;
    nlohmann::json result = {{"job", i + 1}};
    std::string what = "job " + std::to_string(i + 1);
    try {
      interrupt::check(jobsDone());
    } catch (const Interrupted&) {
      report(true);
      throw;
    }
    try {
      if (jobs[i].is_object() && jobs[i].contains("command") && jobs[i]["command"].is_string())
        result["command"] = jobs[i]["command"];
      result["report"] = runJob(jobs[i], base, common, what);
      result["ok"] = true;
    } catch (const Interrupted& e) {
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
  log::info("all " + std::to_string(results.size()) + " jobs" + (a.shard.empty() ? "" : " of part " + a.shard) +
            " succeeded");
}

}  // namespace

void addRunCommand(CLI::App& app, CommonOptions& common)
{
  auto a = std::make_shared<RunArguments>();
  auto* cmd = app.add_subcommand("run", "Run a JSON list of denoise and morph jobs in one process");
  cmd->add_option("jobs", a->jobsFile, "Jobs file: a JSON array of {\"command\": ..., paths, options}")->required();
  cmd->add_flag("--fail-fast", a->failFast, "Stop at the first job that fails");
  cmd->add_option("--shard", a->shard,
                  "Run only part K of N of the jobs (K/N: jobs K, K+N, K+2N, ...), one part per machine or process");
  cmd->callback([&common, a] { runJobs(common, *a); });
}

}  // namespace lbmshape::cli
