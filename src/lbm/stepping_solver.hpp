// What stepping a lattice needs, whatever it is stored on: the whole grid
// (LatticeSolver) or the narrow band (BandSolver). InterruptibleSteps and
// the benchmarks drive either through this.
#pragma once

#include <string>

namespace lbmshape {

class SteppingSolver {
public:
  virtual ~SteppingSolver() = default;
  virtual std::string backendName() const = 0;
  virtual void step(int count) = 0;
  virtual int stepsTaken() const = 0;
};

}  // namespace lbmshape
