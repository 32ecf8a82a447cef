// Host-side bookkeeping that both back ends share: parameter checks and the
// initial density that puts the lattice in equilibrium with a given X.
#pragma once

#include <optional>

#include "lbmshape/core/volume.hpp"
#include "lbmshape/lbm/lattice_solver.hpp"

namespace lbmshape::solver_state {

// omega per cell from gamma per cell, checking every value.
Volume omegaFromGammaVolume(const Volume& gamma);

// The zeroth moment sum_i f_i that makes the solver report `field` at step 0:
// X - S/2 with S = A - c X (just X without a source).
Volume initialDensity(const Volume& field, const std::optional<LinearSource>& source);

// Throws std::invalid_argument when the paper's rule is asked for with a
// source: its X before would have to leave the source's share out.
void checkPaperRuleWithoutSource(bool paperRule, bool source);

void checkSameExtent(const Extent3& expected, const Extent3& got, const char* what);

}  // namespace lbmshape::solver_state
