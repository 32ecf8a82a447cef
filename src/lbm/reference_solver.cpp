#include "lbm/reference_solver.hpp"

#include <array>

#include "lbm/d3q19.hpp"
#include "lbm/relaxation.hpp"
#include "lbm/solver_state.hpp"

namespace lbmshape {

using d3q19::Q;

ReferenceSolver::ReferenceSolver(Extent3 extent)
    : extent_(extent), current_(size_t(Q) * extent.cells()), next_(size_t(Q) * extent.cells())
{
}

void ReferenceSolver::setUniformGamma(double gamma)
{
  relaxation::checkGamma(gamma);
  uniformOmega_ = float(relaxation::omegaFromGamma(gamma));
  omegaPerCell_ = Volume();
}

void ReferenceSolver::setGammaPerCell(const Volume& gamma)
{
  solver_state::checkSameExtent(extent_, gamma.extent(), "gamma");
  omegaPerCell_ = solver_state::omegaFromGammaVolume(gamma);
}

void ReferenceSolver::setSource(std::optional<LinearSource> source)
{
  if (source) solver_state::checkSameExtent(extent_, source->base.extent(), "source");
  source_ = std::move(source);
}

void ReferenceSolver::initialize(const Volume& field)
{
  solver_state::checkSameExtent(extent_, field.extent(), "field");
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
}

void ReferenceSolver::step(int count)
{
  for (int s = 0; s < count; ++s) {
    sweep<true>(nullptr);
    current_.swap(next_);
    ++steps_;
  }
}

Volume ReferenceSolver::field()
{
  Volume out(extent_);
  sweep<false>(&out);
  return out;
}

// One pass over the lattice: pull the distributions of each cell, compute its
// field, and (if Collide) relax and store the post-collision values.
template <bool Collide>
void ReferenceSolver::sweep(Volume* fieldOut)
{
  const Extent3 e = extent_;
  const size_t cells = e.cells();
  const float* cur = current_.data();
  float* nxt = next_.data();
  const float* omegaCell = omegaPerCell_.size() ? omegaPerCell_.data() : nullptr;
  const float* sourceBase = source_ ? source_->base.data() : nullptr;
  const float decay = source_ ? source_->decay : 0.0f;
  const float uniformOmega = uniformOmega_;

#pragma omp parallel for collapse(2) schedule(static)
  for (int z = 0; z < e.nz; ++z) {
    for (int y = 0; y < e.ny; ++y) {
      // Per direction: where this row pulls from, or -1 if that row is outside.
      std::array<long, Q> sourceRow;
      for (int i = 0; i < Q; ++i) {
        const auto& v = d3q19::velocities[i];
        int sy = y - v.y, sz = z - v.z;
        sourceRow[i] = (sy >= 0 && sy < e.ny && sz >= 0 && sz < e.nz) ? long(e.index(0, sy, sz)) : -1;
      }
      const size_t row = e.index(0, y, z);
      for (int x = 0; x < e.nx; ++x) {
        const size_t own = row + size_t(x);
        std::array<float, Q> f;
        for (int i = 0; i < Q; ++i) {
          int sx = x - d3q19::velocities[i].x;
          bool inside = sourceRow[i] >= 0 && sx >= 0 && sx < e.nx;
          f[i] = inside ? cur[size_t(i) * cells + size_t(sourceRow[i]) + size_t(sx)]
                        : cur[size_t(d3q19::opposite(i)) * cells + own];
        }
        float X = 0.0f;
        for (int i = 0; i < Q; ++i) X += f[i];
        float S = 0.0f;
        if (sourceBase) {
          float A = sourceBase[own];
          X = (X + 0.5f * A) / (1.0f + 0.5f * decay);
          S = A - decay * X;
        }
        if constexpr (!Collide) {
          (*fieldOut)[own] = X;
        } else {
          const float omega = omegaCell ? omegaCell[own] : uniformOmega;
          const float sourceShare = 1.0f - 0.5f * omega;
          for (int i = 0; i < Q; ++i) {
            const float w = d3q19::weight(i);
            nxt[size_t(i) * cells + own] = f[i] + omega * (w * X - f[i]) + sourceShare * w * S;
          }
        }
      }
    }
  }
}

}  // namespace lbmshape
