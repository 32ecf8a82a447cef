#include "job_files.hpp"

#include <algorithm>
#include <unordered_map>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/log.hpp"

namespace lbmshape::cli {
namespace {
namespace fs = std::filesystem;

// What a job writes: its output (a file, or a morph's folder) and its
// preview picture, each as an absolute path without a trailing separator.
struct JobWrite {
  fs::path path;
  size_t job;        // 1-based
  std::string text;  // as the jobs file gives it
  bool folder;       // a morph's folder of frames
};

// Paths given in the jobs file (relative to its folder) as one spelling per
// file: absolute, links resolved where they exist, no trailing separator.
// A folder's spelling is kept: resolving every path whole (a realpath of
// each of its folders) took 1.5 s of 200,000 jobs' checks; their outputs
// and inputs lie in a few folders.
class PathSpeller {
public:
  explicit PathSpeller(const fs::path& jobsFile) : base_(jobsFile.parent_path()) {}

  fs::path operator()(const std::string& given)
  {
    std::error_code ec;
    fs::path path = fs::absolute(base_ / given, ec).lexically_normal();
    if (path.has_relative_path() && path.filename().empty()) path = path.parent_path();  // "frames/" is "frames"
    auto [folder, fresh] = folders_.try_emplace(path.parent_path().string());
    if (fresh) {
      folder->second = fs::weakly_canonical(path.parent_path(), ec);
      if (ec) folder->second = path.parent_path();
    }
    fs::path spelled = folder->second / path.filename();
    if (fs::is_symlink(spelled, ec)) {
      const fs::path resolved = fs::weakly_canonical(spelled, ec);
      if (!ec) spelled = resolved;
    }
    return spelled;
  }

private:
  fs::path base_;
  std::unordered_map<std::string, fs::path> folders_;
};

bool isMorph(const nlohmann::json& job) { return job.contains("command") && job["command"] == "morph"; }

std::vector<JobWrite> writesOf(const nlohmann::json& jobs, PathSpeller& oneSpelling)
{
  std::vector<JobWrite> writes;
  for (size_t i = 0; i < jobs.size(); ++i) {
    if (!jobs[i].is_object()) continue;
    for (const char* key : {"output", "preview"}) {
      if (!jobs[i].contains(key) || !jobs[i][key].is_string()) continue;
      const std::string text = jobs[i][key].get<std::string>();
      writes.push_back({oneSpelling(text), i + 1, text, isMorph(jobs[i]) && std::string(key) == "output"});
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

// Two jobs writing the same file, or one writing into another's folder of
// frames: refused, naming both. Sorted by path, so a jobs file of 200,000
// jobs is checked in a moment (pair by pair it took minutes): equal paths
// lie side by side, and what lies inside a folder comes right after it,
// paths comparing component by component.
void requireDistinctOutputs(std::vector<JobWrite> writes, const fs::path& file)
{
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

void warnOfReadsBeforeTheirWrites(const nlohmann::json& jobs, std::vector<JobWrite> writes, PathSpeller& oneSpelling,
                                  const std::function<bool(size_t)>& inThisPart, bool sharded)
{
  std::unordered_map<std::string, JobWrite> written;
  for (JobWrite& w : writes) written.emplace(w.path.string(), std::move(w));
  if (written.empty()) return;
  // The job that writes `path`: the file itself, or the folder of frames it lies in.
  const auto writerOf = [&](const fs::path& path) -> const JobWrite* {
    if (auto found = written.find(path.string()); found != written.end()) return &found->second;
    for (fs::path folder = path.parent_path(); folder.has_relative_path(); folder = folder.parent_path())
      if (auto found = written.find(folder.string()); found != written.end() && found->second.folder)
        return &found->second;
    return nullptr;
  };
  constexpr int mostLines = 10;
  int warned = 0;
  for (size_t i = 0; i < jobs.size(); ++i) {
    const size_t job = i + 1;
    if (!inThisPart(job) || !jobs[i].is_object()) continue;
    for (const char* key :
         isMorph(jobs[i]) ? std::vector<const char*>{"source", "target"} : std::vector<const char*>{"input"}) {
      if (!jobs[i].contains(key) || !jobs[i][key].is_string()) continue;
      const std::string text = jobs[i][key].get<std::string>();
      const JobWrite* writer = writerOf(oneSpelling(text));
      if (!writer || writer->job == job) continue;
      const std::string reader = "job " + std::to_string(job), other = "job " + std::to_string(writer->job);
      std::string message;
      if (sharded && !inThisPart(writer->job))
        message = reader + " reads " + text + ", which " + other +
                  " writes in another part of --shard: the parts run side by side, so " + reader +
                  " may read an older file, or none; run that part first";
      else if (writer->job > job)
        message = reader + " reads " + text + ", which " + other + " writes after it: " + reader +
                  " will read an older file, or none; put " + other + " first";
      else
        continue;
      if (++warned <= mostLines) log::warning(message);
    }
  }
  if (warned > mostLines)
    log::warning("and " + std::to_string(warned - mostLines) + " more jobs that read a file before it is written");
}

}  // namespace

void checkJobFiles(const nlohmann::json& jobs, const fs::path& file, const std::function<bool(size_t)>& inThisPart,
                   bool sharded)
{
  // Spelled once for both checks: resolving the paths is most of their time.
  PathSpeller oneSpelling(file);
  std::vector<JobWrite> writes = writesOf(jobs, oneSpelling);
  requireDistinctOutputs(writes, file);
  warnOfReadsBeforeTheirWrites(jobs, std::move(writes), oneSpelling, inThisPart, sharded);
}

}  // namespace lbmshape::cli
