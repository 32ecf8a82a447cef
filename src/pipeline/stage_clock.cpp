#include "lbmshape/pipeline/stage_clock.hpp"

#include <cstdio>

#include "lbmshape/core/log.hpp"

namespace lbmshape {

namespace {
void addStageTime(std::vector<std::pair<std::string, double>>& stages, const std::string& name, double ms)
{
  for (auto& [stage, total] : stages)
    if (stage == name) {
      total += ms;
      return;
    }
  stages.emplace_back(name, ms);
}

double stageTime(const std::vector<std::pair<std::string, double>>& stages, const std::string& name)
{
  for (const auto& [stage, total] : stages)
    if (stage == name) return total;
  return 0.0;
}
}  // namespace

void StageClock::recordDevice(const std::string& name, double ms)
{
  if (ms > 0.0) addStageTime(deviceStages_, name, ms);
}

double StageClock::deviceMs(const std::string& name) const { return stageTime(deviceStages_, name); }

nlohmann::json StageClock::deviceToJson() const
{
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [stage, total] : deviceStages_) j[stage] = total;
  return j;
}

void StageClock::report(const std::string& name, double ms, double deviceMs)
{
  char line[160];
  if (deviceMs > 0.0)
    std::snprintf(line, sizeof line, "%-8s %8.1f ms (the device busy %.1f ms of it)", name.c_str(), ms, deviceMs);
  else
    std::snprintf(line, sizeof line, "%-8s %8.1f ms", name.c_str(), ms);
  if (ms > 1000.0)
    log::info(line);
  else
    log::verbose(line);
}

void StageClock::record(const std::string& name, double ms) { addStageTime(stages_, name, ms); }

double StageClock::ms(const std::string& name) const { return stageTime(stages_, name); }

nlohmann::json StageClock::toJson() const
{
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [stage, total] : stages_) j[stage] = total;
  j["total"] = totalMs();
  return j;
}

}  // namespace lbmshape
