// Progress of a long stage, on stderr. Nothing is shown for a stage that
// ends within a second; after that a line says how far it is (when the stage
// reports its fraction) and how long it has run, about once a second on a
// terminal (rewritten in place) and every few seconds in a log file.
//
// The stage's work calls advance() from any thread; a reporter thread does
// the printing, so a stage never waits on stderr.
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "lbmshape/core/stopwatch.hpp"

namespace lbmshape {

class Progress {
public:
  // `stage` names the work in the line ("sdf", "lbm"); the reporter starts
  // only when progress is shown at all (not with --quiet).
  explicit Progress(std::string stage);
  ~Progress();  // stops the reporter; a shown line is finished with the total time
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Starts a part of the stage: `part` is shown beside the stage's name
  // ("winding-number sign"), `units` is how much work it holds and `weight`
  // its share of the whole stage (the parts' weights should add up to 1).
  void beginPart(const std::string& part, double units, double weight = 1.0);
  // Records `units` more of the current part as done; safe from any thread.
  void advance(double units = 1.0);

  // The fraction of the stage done, in [0, 1].
  double fraction() const;
  // Whether a line has been written (the reporter has finished writing it
  // when this says so): what a caller, or a test, can wait on.
  bool lineShown() const;

private:
  std::string line() const;

  const std::string stage_;
  const Stopwatch running_;
  mutable std::mutex mutex_;  // guards part_ and the fields of the current part below
  std::string part_;
  double partUnits_ = 0.0, partWeight_ = 0.0, finishedWeight_ = 0.0;
  std::atomic<double> partDone_{0.0};
  bool shown_ = false;
  bool stopping_ = false;
  std::condition_variable wake_;
  std::thread reporter_;
};

// Milliseconds before the first line and between lines (1000 on a terminal,
// 5000 otherwise); LBMSHAPE_PROGRESS_MS sets both, for tests and for logs
// that want more or fewer lines.
struct ProgressTiming {
  double firstMs, everyMs;
  static ProgressTiming current();
};

}  // namespace lbmshape
