// Lattice steps in batches, with a Ctrl-C check between them: a frame of
// thousands of steps must not keep Ctrl-C waiting for it. A step is the same
// whatever batch it is in, so the field never depends on the batch size.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "lbmshape/core/progress.hpp"
#include "lbmshape/lbm/stepping_solver.hpp"

namespace lbmshape {

class InterruptibleSteps {
public:
  // Batches last about `batchMs` each, sized by the speed measured so far,
  // unless `fixedBatch` sets their size (for tests).
  explicit InterruptibleSteps(SteppingSolver& solver, std::optional<int> fixedBatch = std::nullopt,
                              double batchMs = 250.0);

  // Steps until the solver has taken `totalSteps` in all. Before each batch,
  // throws Interrupted with whatWasDone() if Ctrl-C was pressed; after each,
  // tells `progress` (if any) how many steps it took.
  void advanceTo(int totalSteps, const std::function<std::string()>& whatWasDone, Progress* progress = nullptr);

private:
  int nextBatch(int remaining) const;

  SteppingSolver& solver_;
  std::optional<int> fixedBatch_;
  double batchMs_;
  double msPerStep_ = 0.0;  // measured; 0 until the first batch
  int lastBatch_ = 1;
};

}  // namespace lbmshape
