#include "lbmshape/core/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <unistd.h>

#include "lbmshape/core/log.hpp"

namespace lbmshape {

ProgressTiming ProgressTiming::current()
{
  // A number of milliseconds, at most a day (a wait far longer overflows the
  // clock's arithmetic, and the reporter would spin); anything else is
  // ignored.
  if (const char* ms = std::getenv("LBMSHAPE_PROGRESS_MS")) {
    char* end = nullptr;
    const double value = std::strtod(ms, &end);
    if (end != ms && *end == '\0' && std::isfinite(value) && value >= 0.0) {
      const double bounded = std::min(value, 86400e3);
      return {bounded, std::max(bounded, 1.0)};
    }
    static std::once_flag said;  // once a process, not once a stage
    std::call_once(said, [ms] {
      log::warning("LBMSHAPE_PROGRESS_MS=" + std::string(ms) +
                   " is not a number of milliseconds of 0 or more; ignored (0 shows every stage's progress)");
    });
  }
  // A terminal line is rewritten in place, so it can change often; a log
  // file keeps every line, so it gets fewer.
  if (isatty(STDERR_FILENO)) return {1000.0, 1000.0};
  return {1000.0, 5000.0};
}

Progress::Progress(std::string stage) : stage_(std::move(stage))
{
  if (log::level() < log::Level::Normal) return;
  const ProgressTiming timing = ProgressTiming::current();
  reporter_ = std::thread([this, timing] {
    std::unique_lock lock(mutex_);
    double wait = timing.firstMs;
    std::string last;
    while (!wake_.wait_for(lock, std::chrono::duration<double, std::milli>(wait), [this] { return stopping_; })) {
      wait = timing.everyMs;
      // A line the same as the last says nothing new: at a short interval
      // (LBMSHAPE_PROGRESS_MS=0) a 2 s denoise wrote 1,591 lines, most of
      // them repeats ("sdf 80% (winding-number sign), 1.0 s" 93 times).
      std::string text = line();
      if (text == last) continue;
      shown_ = true;
      log::progress(text);
      last = std::move(text);
    }
  });
}

Progress::~Progress()
{
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (reporter_.joinable()) reporter_.join();
  if (shown_) log::endProgress();
}

bool Progress::lineShown() const
{
  // The reporter holds the lock from setting shown_ until the line is out.
  std::lock_guard lock(mutex_);
  return shown_;
}

void Progress::beginPart(const std::string& part, double units, double weight)
{
  std::lock_guard lock(mutex_);
  if (partUnits_ > 0.0 || !part_.empty()) finishedWeight_ += partWeight_;
  part_ = part;
  partUnits_ = units;
  partWeight_ = weight;
  partDone_ = 0.0;
}

void Progress::advance(double units) { partDone_.fetch_add(units, std::memory_order_relaxed); }

double Progress::fraction() const
{
  std::lock_guard lock(mutex_);
  const double inPart = partUnits_ > 0.0 ? std::min(1.0, partDone_.load(std::memory_order_relaxed) / partUnits_) : 0.0;
  return std::clamp(finishedWeight_ + partWeight_ * inPart, 0.0, 1.0);
}

// Called with mutex_ held.
std::string Progress::line() const
{
  char text[160];
  const double seconds = running_.ms() * 1e-3;
  if (part_.empty()) {
    std::snprintf(text, sizeof text, "%s... %.1f s", stage_.c_str(), seconds);
  } else {
    const double inPart =
        partUnits_ > 0.0 ? std::min(1.0, partDone_.load(std::memory_order_relaxed) / partUnits_) : 0.0;
    const double done = std::clamp(finishedWeight_ + partWeight_ * inPart, 0.0, 1.0);
    std::snprintf(text, sizeof text, "%s %3.0f%% (%s), %.1f s", stage_.c_str(), 100.0 * done, part_.c_str(), seconds);
  }
  return text;
}

}  // namespace lbmshape
