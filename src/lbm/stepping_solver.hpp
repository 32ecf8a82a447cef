// What stepping a lattice needs, whatever it is stored on: the whole grid
// (LatticeSolver) or the narrow band (BandSolver). InterruptibleSteps and
// the benchmarks drive either through this.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

namespace lbmshape {

// A linear source's decay c and scale k (setSourceStrength's arguments).
struct SourceStrength {
  float decay = 0.0f;
  float scale = 1.0f;
};

class SteppingSolver {
public:
  virtual ~SteppingSolver() = default;
  virtual std::string backendName() const = 0;
  virtual void step(int count) = 0;
  virtual int stepsTaken() const = 0;

protected:
  // For setPaperRule(): it takes effect at initialize(), which seeds each
  // cell's X before and gamma; stepping between the two would read neither.
  static void requirePaperRuleInitialized(bool set, bool initialized)
  {
    if (set && !initialized) throw std::logic_error("setPaperRule takes effect at initialize(): initialize first");
  }

  // For setSourceStrength(): it changes a source that is there.
  template <typename Source>
  static void setStrength(std::optional<Source>& source, float decay, float scale)
  {
    if (!source) throw std::logic_error("setSourceStrength without a source: setSource first");
    source->decay = decay;
    source->scale = scale;
  }

  // For previousField(): the copy the last step read is the state one step
  // earlier, provided two steps were taken (a narrow band's first step only
  // marks its initial state as stepped).
  void requireTwoSteps() const
  {
    if (stepsTaken() < 2) throw std::logic_error("the field before the last step needs two steps taken");
  }
};

}  // namespace lbmshape
