// Wall-clock time of each stage of a job, for --verbose and the JSON report.
#pragma once

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/interrupt.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"

namespace lbmshape {

class StageClock {
public:
  // Runs `work`, records its time under `name`, and logs it (always when it
  // took over a second, so slow stages are never silent; else with --verbose).
  // A stage running longer than a second shows a progress line meanwhile;
  // `work` that takes a Progress& reports how far it is through it.
  // Ctrl-C (see core/interrupt.hpp) is honoured before each stage starts.
  template <class Work>
  decltype(auto) time(const std::string& name, Work&& work)
  {
    interrupt::check("stopped before the " + name + " stage");
    Stopwatch watch;
    struct Record {
      StageClock& clock;
      const std::string& name;
      Stopwatch& watch;
      ~Record() { clock.record(name, watch.ms()), clock.report(name, watch.ms()); }
    } record{*this, name, watch};
    Progress progress(name);
    if constexpr (std::is_invocable_v<Work, Progress&>) return std::forward<Work>(work)(progress);
    else return std::forward<Work>(work)();
  }

  // Adds `ms` to the stage's total (stages repeated per frame accumulate).
  void record(const std::string& name, double ms);
  // Logs one stage's time: always over a second, else with --verbose.
  static void report(const std::string& name, double ms);
  double ms(const std::string& name) const;
  double totalMs() const { return total_.ms(); }
  nlohmann::json toJson() const;  // {"stage": ms, ..., "total": ms}

private:
  std::vector<std::pair<std::string, double>> stages_;
  Stopwatch total_;
};

}  // namespace lbmshape
