#include "lbmshape/lbm/reference_solver.hpp"

#include <array>
#include <vector>

#include "lbmshape/lbm/adaptive_gamma.hpp"
#include "lbmshape/lbm/d3q19.hpp"
#include "lbmshape/lbm/relaxation.hpp"
#include "lbmshape/lbm/solver_state.hpp"

namespace lbmshape {

using d3q19::Q;

ReferenceSolver::ReferenceSolver(Extent3 extent)
    : extent_(extent), current_(size_t(Q) * extent.cells()), next_(size_t(Q) * extent.cells())
{}

void ReferenceSolver::setUniformGamma(double gamma)
{
  relaxation::checkGamma(gamma);
  uniformOmega_ = float(relaxation::omegaFromGamma(gamma));
  omegaPerCell_ = Volume();
  paperRuleGamma0_.reset();
}

void ReferenceSolver::setGammaPerCell(const Volume& gamma)
{
  solver_state::checkSameExtent(extent_, gamma.extent(), "gamma");
  omegaPerCell_ = solver_state::omegaFromGammaVolume(gamma);
  paperRuleGamma0_.reset();
}

void ReferenceSolver::setPaperRule(double gamma0)
{
  setUniformGamma(gamma0);
  paperRuleGamma0_ = gamma0;
  paperRuleReady_ = false;
}

void ReferenceSolver::applyPaperRule()
{
  Volume x = field();
  gammaBefore_ = adaptive_gamma::paperRule(xBefore_, x, gammaBefore_, *paperRuleGamma0_);
  omegaPerCell_ = solver_state::omegaFromGammaVolume(gammaBefore_);
  xBefore_ = std::move(x);
}

void ReferenceSolver::setSource(std::optional<LinearSource> source)
{
  if (source) solver_state::checkSameExtent(extent_, source->base.extent(), "source");
  source_ = std::move(source);
}

void ReferenceSolver::setSourceStrength(float decay, float scale) { setStrength(source_, decay, scale); }

void ReferenceSolver::initialize(const Volume& field)
{
  solver_state::checkSameExtent(extent_, field.extent(), "field");
  solver_state::checkPaperRuleWithoutSource(paperRuleGamma0_.has_value(), source_.has_value());
  Volume density = solver_state::initialDensity(field, source_);
  // Store f* so that the next pull delivers f_i(r) = w_i density(r): the value
  // streamed along e_j out of q belongs to q + e_j, or to q itself when q + e_j
  // is outside and the wall bounces it back.
  const Extent3 e = extent_;
#pragma omp parallel for collapse(2) schedule(static)
  for (int z = 0; z < e.nz; ++z)
    for (int y = 0; y < e.ny; ++y)
      for (int x = 0; x < e.nx; ++x)
        for (int j = 0; j < Q; ++j) {
          const auto& v = d3q19::velocities[j];
          int tx = x + v.x, ty = y + v.y, tz = z + v.z;
          float target = e.contains(tx, ty, tz) ? density.at(tx, ty, tz) : density.at(x, y, z);
          distribution(current_, j)[e.index(x, y, z)] = d3q19::weight(j) * target;
        }
  steps_ = 0;
  if (paperRuleGamma0_) {
    // The first step's X before is what it pulls: gamma0 is its gamma.
    xBefore_ = this->field();
    gammaBefore_ = Volume(extent_, float(*paperRuleGamma0_));
    paperRuleReady_ = true;
  }
}

void ReferenceSolver::step(int count)
{
  requirePaperRuleInitialized(paperRuleGamma0_.has_value(), paperRuleReady_);
  for (int s = 0; s < count; ++s) {
    if (paperRuleGamma0_) applyPaperRule();
    sweep<true>(nullptr);
    current_.swap(next_);
    ++steps_;
  }
}

Volume ReferenceSolver::previousField()
{
  requireTwoSteps();
  current_.swap(next_);
  Volume out = field();
  current_.swap(next_);
  return out;
}

Volume ReferenceSolver::field()
{
  Volume out(extent_);
  sweep<false>(&out);
  return out;
}

namespace {

// Everything one pass needs to know about the lattice.
struct SweepState {
  Extent3 extent;
  const float* current;  // post-collision f* of the last step, SoA
  float* next;           // where the step stores the new f*
  float* field;          // where a field pass stores X
  const float* omegaPerCell;
  float uniformOmega;
  const float* sourceBase;
  float decay;
  float baseScale;
};

// The update of one cell from its pulled distributions f. The flags are
// template parameters so that the row loop has no branches and vectorises.
template <bool Collide, bool PerCellOmega, bool HasSource>
inline void updateCell(const SweepState& s, size_t own, const float* f)
{
  float X = 0.0f;
#pragma GCC unroll 19
  for (int i = 0; i < Q; ++i) X += f[i];
  float S = 0.0f;
  if constexpr (HasSource) {
    float A = s.baseScale * s.sourceBase[own];
    X = (X + 0.5f * A) / (1.0f + 0.5f * s.decay);
    S = A - s.decay * X;
  }
  if constexpr (!Collide) {
    s.field[own] = X;
  } else {
    const size_t cells = s.extent.cells();
    const float omega = PerCellOmega ? s.omegaPerCell[own] : s.uniformOmega;
    const float sourceShare = 1.0f - 0.5f * omega;
#pragma GCC unroll 19
    for (int i = 0; i < Q; ++i) {
      const float w = d3q19::weight(i);
      s.next[size_t(i) * cells + own] = f[i] + omega * (w * X - f[i]) + sourceShare * w * S;
    }
  }
}

// Scratch space of one thread for one row: the field, source and relaxation
// of every cell of the row.
struct RowScratch {
  explicit RowScratch(int nx) : X(size_t(nx)), S(size_t(nx)), omega(size_t(nx)) {}
  std::vector<float> X, S, omega;
};

// One row (y, z). Per direction i the row streams from one contiguous source:
// the upstream row shifted by e_i.x, or, where the upstream row is outside,
// the cell's own opposite distribution (bounce-back). Between the two x walls
// the update is then a few plain loops over x, one direction at a time, that
// the compiler vectorises; the cells at the x walls take the per-cell path
// that also bounces in x. The arithmetic is the same, in the same order, as
// in updateCell and in the shader.
template <bool Collide, bool PerCellOmega, bool HasSource>
void sweepRow(const SweepState& s, int y, int z, RowScratch& scratch)
{
  const Extent3& e = s.extent;
  const size_t cells = e.cells();
  const size_t row = e.index(0, y, z);
  std::array<const float*, Q> source;  // source[i][x]: f*_i that reaches (x, y, z)
  std::array<bool, Q> rowInside;
  for (int i = 0; i < Q; ++i) {
    const auto& v = d3q19::velocities[i];
    int sy = y - v.y, sz = z - v.z;
    rowInside[i] = sy >= 0 && sy < e.ny && sz >= 0 && sz < e.nz;
    source[i] = rowInside[i] ? s.current + size_t(i) * cells + e.index(0, sy, sz) - v.x
                             : s.current + size_t(d3q19::opposite(i)) * cells + row;
  }
  auto wallCell = [&](int x) {
    std::array<float, Q> f;
    for (int i = 0; i < Q; ++i) {
      int sx = x - d3q19::velocities[i].x;
      f[i] = (rowInside[i] && sx >= 0 && sx < e.nx) ? source[i][x]
                                                    : s.current[size_t(d3q19::opposite(i)) * cells + row + size_t(x)];
    }
    updateCell<Collide, PerCellOmega, HasSource>(s, row + size_t(x), f.data());
  };
  wallCell(0);
  if (e.nx > 1) wallCell(e.nx - 1);
  if (e.nx <= 2) return;

  const int first = 1, last = e.nx - 1;  // interior cells [first, last)
  float* __restrict X = scratch.X.data();
  float* __restrict S = scratch.S.data();
  float* __restrict omega = scratch.omega.data();
  {
    const float* __restrict f0 = source[0];
    for (int x = first; x < last; ++x) X[x] = f0[x];
  }
  for (int i = 1; i < Q; ++i) {
    const float* __restrict fi = source[i];
    for (int x = first; x < last; ++x) X[x] += fi[x];
  }
  if constexpr (HasSource) {
    const float* __restrict base = s.sourceBase + row;
    const float decay = s.decay, scale = s.baseScale;
    for (int x = first; x < last; ++x) {
      const float A = scale * base[x];
      X[x] = (X[x] + 0.5f * A) / (1.0f + 0.5f * decay);
      S[x] = A - decay * X[x];
    }
  } else {
    for (int x = first; x < last; ++x) S[x] = 0.0f;
  }
  if constexpr (!Collide) {
    float* __restrict out = s.field + row;
    for (int x = first; x < last; ++x) out[x] = X[x];
  } else {
    for (int x = first; x < last; ++x) omega[x] = PerCellOmega ? s.omegaPerCell[row + size_t(x)] : s.uniformOmega;
    for (int i = 0; i < Q; ++i) {
      const float w = d3q19::weight(i);
      const float* __restrict fi = source[i];
      float* __restrict out = s.next + size_t(i) * cells + row;
      for (int x = first; x < last; ++x) {
        const float sourceShare = 1.0f - 0.5f * omega[x];
        out[x] = fi[x] + omega[x] * (w * X[x] - fi[x]) + sourceShare * w * S[x];
      }
    }
  }
}

template <bool Collide, bool PerCellOmega, bool HasSource>
void sweepAll(const SweepState& s)
{
#pragma omp parallel
  {
    RowScratch scratch(s.extent.nx);
#pragma omp for collapse(2) schedule(static)
    for (int z = 0; z < s.extent.nz; ++z)
      for (int y = 0; y < s.extent.ny; ++y) sweepRow<Collide, PerCellOmega, HasSource>(s, y, z, scratch);
  }
}

}  // namespace

// One pass over the lattice: pull the distributions of each cell, compute its
// field, and (if Collide) relax and store the post-collision values.
template <bool Collide>
void ReferenceSolver::sweep(Volume* fieldOut)
{
  SweepState s{extent_,
               current_.data(),
               next_.data(),
               fieldOut ? fieldOut->data() : nullptr,
               omegaPerCell_.size() ? omegaPerCell_.data() : nullptr,
               uniformOmega_,
               source_ ? source_->base.data() : nullptr,
               source_ ? source_->decay : 0.0f,
               source_ ? source_->scale : 1.0f};
  const bool perCell = s.omegaPerCell != nullptr, withSource = s.sourceBase != nullptr;
  if (perCell && withSource)
    sweepAll<Collide, true, true>(s);
  else if (perCell)
    sweepAll<Collide, true, false>(s);
  else if (withSource)
    sweepAll<Collide, false, true>(s);
  else
    sweepAll<Collide, false, false>(s);
}

}  // namespace lbmshape
