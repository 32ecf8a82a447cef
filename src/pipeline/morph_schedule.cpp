#include "lbmshape/pipeline/morph_schedule.hpp"

#include <algorithm>
#include <cmath>

#include "lbmshape/core/parameter_bounds.hpp"
#include "lbmshape/pipeline/morph.hpp"

namespace lbmshape {

MorphSchedule::MorphSchedule(double gamma, double cs, double gammaEnd, double csEnd, int totalSteps, int annealFrom,
                             int frames)
    : gamma_(gamma), cs_(cs), gammaEnd_(gammaEnd), csEnd_(csEnd), totalSteps_(totalSteps), annealFrom_(annealFrom),
      frameSteps_(size_t(frames))
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
  return MorphSchedule(o.gamma, o.cs, std::min(o.gamma, arrivalGamma), std::max(o.cs, arrivalCs), total, total / 2,
                       o.frames);
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
