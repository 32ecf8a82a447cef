#include "pipeline/stage_clock.hpp"

#include <cstdio>

#include "core/log.hpp"

namespace lbmshape {

void StageClock::record(const std::string& name, double ms)
{
  for (auto& [stage, total] : stages_)
    if (stage == name) {
      total += ms;
      return;
    }
  stages_.emplace_back(name, ms);
}

void StageClock::report(const std::string& name, double ms)
{
  char line[128];
  std::snprintf(line, sizeof line, "%-8s %8.1f ms", name.c_str(), ms);
  if (ms > 1000.0) log::info(line);
  else log::verbose(line);
}

double StageClock::ms(const std::string& name) const
{
  for (const auto& [stage, total] : stages_)
    if (stage == name) return total;
  return 0.0;
}

nlohmann::json StageClock::toJson() const
{
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [stage, total] : stages_) j[stage] = total;
  j["total"] = totalMs();
  return j;
}

}  // namespace lbmshape
