#include "lbmshape/pipeline/morph_schedule.hpp"

#include <algorithm>
#include <cmath>

#include "lbmshape/core/parameter_bounds.hpp"
#include "lbmshape/pipeline/morph.hpp"

namespace lbmshape {

MorphSchedule::MorphSchedule(double gamma, double cs, double gammaEnd, double csEnd, int totalSteps, int annealFrom,
                             int frames, double scale)
    : gamma_(gamma), cs_(cs), gammaEnd_(gammaEnd), csEnd_(csEnd), totalSteps_(totalSteps), annealFrom_(annealFrom),
      scale_(scale), frameSteps_(size_t(frames))
{
  const int intervals = frames - 1;
  for (int k = 0; k < frames; ++k) frameSteps_[size_t(k)] = int(std::lround(double(totalSteps) * k / intervals));
}

MorphSchedule MorphSchedule::fixed(const MorphOptions& o)
{
  const int total = int(givenStepCount(o));
  return MorphSchedule(o.gamma, o.cs, o.gamma, o.cs, total, total, o.frames);
}

int MorphSchedule::stepsToArrive(double initialError, double cs, double tolerance)
{
  // Already there (a shape into itself): no step, every frame the source.
  if (!(initialError > tolerance)) return 0;
  const double shrinkPerStep = std::log((1.0 + cs / 2.0) / (1.0 - cs / 2.0));  // ln(1/rho)
  const double steps = std::ceil(std::log(initialError / tolerance) / shrinkPerStep);
  return int(std::clamp(steps, 1.0, double(parameter_bounds::maxSteps)));
}

MorphSchedule MorphSchedule::arriving(const MorphOptions& o, double initialError)
{
  const int total = stepsToArrive(initialError, o.cs, o.tolerance);
  const double scale = evenStepsScale(initialError, o, total);
  const int steps = scale != 1.0 ? stepsToArrive(initialError, o.cs * scale, o.tolerance) : total;
  return MorphSchedule(o.gamma * scale, o.cs * scale, std::min(o.gamma, arrivalGamma) * scale,
                       std::max(o.cs, arrivalCs) * scale, steps, steps / 2, o.frames, scale);
}

double MorphSchedule::evenStepsScale(double initialError, const MorphOptions& o, int steps)
{
  const int intervals = o.frames - 1;
  if (steps == 0 || intervals <= 0) return 1.0;
  // The whole number of steps a frame nearest the morph's own: at least
  // one, and where the morph has as many steps as intervals or more, the
  // factor within 3/4 to 3/2 (a Cs of 1 becomes at most 1.5, where the
  // second-order source stays monotone up to 2).
  const long perFrame = std::max(1L, std::lround(double(steps) / intervals));
  const long needed = perFrame * intervals;
  if (needed == steps || needed > parameter_bounds::maxSteps) return 1.0;
  // ln(1/rho(c)) = 2 artanh(c/2): the Cs whose steps to arrive are `needed`
  // (a hair faster, so that rounding does not make them one more).
  const double shrinkPerStep = std::log(initialError / o.tolerance) / needed * (1.0 + 1e-9);
  double cs = 2.0 * std::tanh(shrinkPerStep / 2.0);
  for (int tries = 0; tries < 100 && stepsToArrive(initialError, cs, o.tolerance) < needed; ++tries) cs *= 0.999;
  return cs / o.cs;
}

double MorphSchedule::gammaAt(int step) const
{
  if (step < annealFrom_) return gamma_;
  return gammaEnd_ + (gamma_ - gammaEnd_) * closingLeft(step);
}

double MorphSchedule::csAt(int step) const
{
  if (step < annealFrom_) return cs_;
  return csEnd_ + (cs_ - csEnd_) * closingLeft(step);
}

// From 1 before the closing to 0 at its last step, along a parabola: the
// values leave their first ones gradually and settle at the end.
double MorphSchedule::closingLeft(int step) const
{
  const double left = 1.0 - double(step - annealFrom_ + 1) / double(totalSteps_ - annealFrom_);
  return left * left;
}

int MorphSchedule::sameStepsUntil(int step) const
{
  if (step < annealFrom_) return annealFrom_;
  return std::min(step + 1, totalSteps_);
}

double MorphSchedule::totalDiffusion() const
{
  double sum = 0.0;
  for (int s = 0; s < totalSteps_; ++s) sum += gammaAt(s);
  return sum;
}

}  // namespace lbmshape
