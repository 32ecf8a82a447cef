// Wall-clock time of each stage of a job, for --verbose and the JSON report.
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/progress.hpp"
#include "lbmshape/core/stopwatch.hpp"

namespace lbmshape {

class StageClock {
public:
  StageClock() = default;
  // With `deviceMs`, the device's busy time so far (ComputeDevice::
  // deviceBusyMs): each stage also records how much of it fell within the
  // stage, so that a stage's wall time can be set beside the device's.
  explicit StageClock(std::function<double()> deviceMs) : deviceMs_(std::move(deviceMs)) {}

  // Runs `work`, records its time under `name`, and logs it (always when it
  // took over a second, so slow stages are never silent; else with --verbose).
  // A stage running longer than a second shows a progress line meanwhile;
  // `work` that takes a Progress& reports how far it is through it.
  // Ctrl-C (see core/interrupt.hpp) is honoured before each stage starts,
  // saying what is complete (describeProgressWith).
  template <class Work>
  decltype(auto) time(const std::string& name, Work&& work)
  {
    // (The message follows what stopped it: "interrupted: ", "stopped: ".)
    interrupt::check([&] { return whatIsDone_ ? whatIsDone_() : "before the " + name + " stage"; });
    Stopwatch watch;
    struct Record {
      StageClock& clock;
      const std::string& name;
      Stopwatch& watch;
      double deviceBefore;
      ~Record()
      {
        const double device = clock.deviceMsNow() - deviceBefore;
        clock.record(name, watch.ms());
        clock.recordDevice(name, device);
        clock.report(name, watch.ms(), device);
      }
    } record{*this, name, watch, deviceMsNow()};
    Progress progress(name);
    if constexpr (std::is_invocable_v<Work, Progress&>)
      return std::forward<Work>(work)(progress);
    else
      return std::forward<Work>(work)();
  }

  // What a stop before the next stage says is complete ("nothing was
  // written", "12 complete frames in frames/"), as the job knows it; by
  // default the stage it stopped before, which told a user nothing of the
  // files.
  void describeProgressWith(std::function<std::string()> whatIsDone) { whatIsDone_ = std::move(whatIsDone); }

  // Adds `ms` to the stage's total (stages repeated per frame accumulate).
  void record(const std::string& name, double ms);
  // The same for the device's busy time within the stage.
  void recordDevice(const std::string& name, double ms);
  // Logs one stage's time: always over a second, else with --verbose; with
  // the device's busy time within it where there was any.
  static void report(const std::string& name, double ms, double deviceMs = 0.0);
  double ms(const std::string& name) const;
  double deviceMs(const std::string& name) const;
  // The device's busy time so far (0 without a device).
  double deviceMsNow() const { return deviceMs_ ? deviceMs_() : 0.0; }
  double totalMs() const { return total_.ms(); }
  nlohmann::json toJson() const;        // {"stage": ms, ..., "total": ms}
  nlohmann::json deviceToJson() const;  // {"stage": device ms} for the stages where the device worked

private:
  std::vector<std::pair<std::string, double>> stages_, deviceStages_;
  std::function<double()> deviceMs_;
  std::function<std::string()> whatIsDone_;  // describeProgressWith
  Stopwatch total_;
};

}  // namespace lbmshape
