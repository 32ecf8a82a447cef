#pragma once

#include <chrono>

namespace lbmshape {

// Wall-clock milliseconds since construction or the last restart().
class Stopwatch {
public:
  Stopwatch() : start_(Clock::now()) {}
  void restart() { start_ = Clock::now(); }
  double ms() const { return std::chrono::duration<double, std::milli>(Clock::now() - start_).count(); }

private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

}  // namespace lbmshape
