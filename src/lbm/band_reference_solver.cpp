#include "lbmshape/lbm/band_reference_solver.hpp"

#include "lbmshape/lbm/adaptive_gamma.hpp"
#include "lbmshape/lbm/band_state.hpp"
#include "lbmshape/lbm/d3q19.hpp"
#include "lbmshape/lbm/relaxation.hpp"
#include "lbmshape/lbm/solver_state.hpp"
#include "lbmshape/lbm/surface_change.hpp"

namespace lbmshape {

using d3q19::Q;

namespace {

// X and J of the f a cell pulls.
struct Pulled {
  float X;
  glm::vec3 J;
};

// The f streaming cell `c` (at `l` in its brick, whose neighbours are
// `around`) pulls: from the cells upstream, or bouncing back at a wall (or,
// never for a streaming cell, the band's edge).
Pulled pull(const glm::vec4* current, const int32_t* around, const Extent3& e, glm::ivec3 c, glm::ivec3 l,
            glm::vec4 own)
{
  float f[Q];
  for (int q = 0; q < Q; ++q) {
    const auto& v = d3q19::velocities[q];
    const glm::vec3 ev(float(v.x), float(v.y), float(v.z));
    glm::vec4 from = own;
    float sign = 1.0f;
    const glm::ivec3 up = c - glm::ivec3(v.x, v.y, v.z);
    const glm::ivec3 shifted = l - glm::ivec3(v.x, v.y, v.z);
    const int32_t slot = around[((shifted.x >> 3) + 1) + 3 * ((shifted.y >> 3) + 1) + 9 * ((shifted.z >> 3) + 1)];
    if (e.contains(up.x, up.y, up.z) && slot != noBrick)
      from = current[size_t(slot) * brickCells + size_t(cellInBrick(shifted.x & 7, shifted.y & 7, shifted.z & 7))];
    else
      sign = -1.0f;  // bounce-back: f*_opposite(x)
    f[q] = d3q19::weight(q) * (from.x + sign * 3.0f * (ev.x * from.y + ev.y * from.z + ev.z * from.w));
  }
  Pulled out{0.0f, glm::vec3(0.0f)};
  for (int q = 0; q < Q; ++q) out.X += f[q];
  for (int q = 0; q < Q; ++q) {
    const auto& v = d3q19::velocities[q];
    out.J += glm::vec3(float(v.x), float(v.y), float(v.z)) * f[q];
  }
  return out;
}

}  // namespace

BandReferenceSolver::BandReferenceSolver(std::shared_ptr<const BrickSet> bricks)
    : bricks_(std::move(bricks)), neighbours_(bricks_->neighbourTable()), current_(bricks_->storedCells()),
      next_(bricks_->storedCells()), streams_(bricks_->storedCells(), 0), frozen_(bricks_->activeCount())
{}

void BandReferenceSolver::setUniformGamma(double gamma)
{
  relaxation::checkGamma(gamma);
  uniformOmega_ = float(relaxation::omegaFromGamma(gamma));
  omegaPerCell_.clear();
  paperRuleGamma0_.reset();
}

void BandReferenceSolver::setGammaPerCell(const BandField& gamma)
{
  band_state::checkSameBricks(*bricks_, gamma, "gamma");
  omegaPerCell_ = band_state::omegaFromGamma(gamma);
  paperRuleGamma0_.reset();
}

void BandReferenceSolver::setPaperRule(double gamma0)
{
  setUniformGamma(gamma0);
  paperRuleGamma0_ = gamma0;
  paperRuleReady_ = false;
}

void BandReferenceSolver::applyPaperRule()
{
  BandField x = field();
  gammaBefore_ = adaptive_gamma::paperRule(xBefore_, x, gammaBefore_, *paperRuleGamma0_);
  omegaPerCell_ = band_state::omegaFromGamma(gammaBefore_);
  xBefore_ = std::move(x);
}

void BandReferenceSolver::setSource(std::optional<BandSource> source)
{
  if (source) band_state::checkSameBricks(*bricks_, source->base, "source");
  source_ = std::move(source);
}

void BandReferenceSolver::setSourceStrength(float decay, float scale) { setStrength(source_, decay, scale); }

void BandReferenceSolver::setHeldBricks(std::vector<uint8_t> heldPerSlot)
{
  band_state::checkHeldBricks(heldPerSlot, *bricks_);
  for (const FrozenBricks::CatchUp& group : frozen_.setMotion(heldPerSlot, steps_)) {
    std::vector<glm::vec4>& from = copy(group.copy);
#pragma omp parallel for schedule(static)
    for (size_t k = 0; k < group.slots.size(); ++k)
      for (size_t i = size_t(group.slots[k]) * brickCells; i < size_t(group.slots[k] + 1) * brickCells; ++i)
        current_[i] = heldStep(from[i], i, group.decay, group.omega);
  }
  heldSlots_ = std::move(heldPerSlot);
}

BandReferenceSolver::Sourced BandReferenceSolver::withSource(float sum, size_t i, float decay, float scale) const
{
  if (!source_) return {sum, 0.0f};
  const float a = scale * source_->base.values()[i];
  const float X = (sum + 0.5f * a) / (1.0f + 0.5f * decay);
  return {X, a - decay * X};
}

glm::vec4 BandReferenceSolver::heldStep(glm::vec4 own, size_t i, float c, float omega) const
{
  const auto [X, S] = withSource(own.x, i, c, c);
  return glm::vec4(X + 0.5f * S, (1.0f - omega) * glm::vec3(own.y, own.z, own.w));
}

void BandReferenceSolver::freezeBeforeSteps(int count)
{
  const FrozenBricks::StepParameters p{
      source_.has_value(), source_ ? source_->decay : 0.0f, source_ ? source_->scale : 1.0f,
      uniformOmega_,       !omegaPerCell_.empty(),          paperRuleGamma0_.has_value()};
  const std::vector<int32_t> freezing = frozen_.beforeSteps(count, p, steps_, currentCopy_);
  if (freezing.empty()) return;
  // X of the state they freeze with, as a field pass (sweep<false>) makes it.
  if (frozenField_.empty()) frozenField_.assign(current_.size(), 0.0f);
  for (int32_t s : freezing)
    for (size_t i = size_t(s) * brickCells; i < size_t(s + 1) * brickCells; ++i)
      frozenField_[i] = withSource(current_[i].x, i, p.decay, p.scale).X;
}

void BandReferenceSolver::initialize(BandField field, std::vector<uint8_t> streams)
{
  band_state::checkSameBricks(*bricks_, field, "field");
  solver_state::checkPaperRuleWithoutSource(paperRuleGamma0_.has_value(), source_.has_value());
  if (paperRuleGamma0_) {
    xBefore_ = field;
    gammaBefore_ = BandField(field.sharedBricks(), float(*paperRuleGamma0_));
    std::fill(gammaBefore_.values().begin(), gammaBefore_.values().end(), float(*paperRuleGamma0_));
    paperRuleReady_ = true;
  }
  current_ = band_state::collidedEquilibrium(field, source_);
  next_ = current_;  // bricks a step skips keep their moments in both copies
  currentCopy_ = 0;
  frozen_.start();
  if (streams.size() != field.values().size()) throw std::invalid_argument("one streaming flag a stored cell");
  streams_ = band_state::onlyCellsInTheGrid(std::move(streams), *bricks_);
  work_ = band_state::slotsToStep(*bricks_, streams_, source_.has_value());
  workHasSource_ = source_.has_value();
  initial_ = std::move(field);
  steps_ = 0;
}

// The reference keeps its initial field whole anyway (field() reads its far
// sides from it).
void BandReferenceSolver::holdFieldForRestart() {}

void BandReferenceSolver::restart()
{
  band_state::checkRestart(!initial_.values().empty(), workHasSource_, source_.has_value());
  BandField field = initial_;
  std::vector<uint8_t> streams = streams_;
  initialize(std::move(field), std::move(streams));
}

void BandReferenceSolver::step(int count)
{
  requirePaperRuleInitialized(paperRuleGamma0_.has_value(), paperRuleReady_);
  // The state initialize() leaves is already the one after the first step
  // (band_state::collidedEquilibrium): that step costs nothing.
  if (count > 0 && steps_ == 0) --count, ++steps_;
  freezeBeforeSteps(count);
  for (int s = 0; s < count; ++s) {
    if (paperRuleGamma0_) applyPaperRule();
    sweep<true>(nullptr);
    current_.swap(next_);
    currentCopy_ = 1 - currentCopy_;
    ++steps_;
  }
}

BandField BandReferenceSolver::previousField()
{
  requireTwoSteps();
  current_.swap(next_);
  currentCopy_ = 1 - currentCopy_;
  BandField out = field();
  current_.swap(next_);
  currentCopy_ = 1 - currentCopy_;
  return out;
}

BandField BandReferenceSolver::storedField(int back)
{
  band_state::checkStoredField(back, steps_, source_.has_value());
  // After a step, current_ holds what it collided and next_ what the step
  // before collided; the first, free step leaves both at the initial state.
  const std::vector<glm::vec4>& copy = back == 1 ? current_ : next_;
  BandField out = initial_.sameShape();
  for (size_t i = 0; i < copy.size(); ++i) out.values()[i] = copy[i].x;
  return out;
}

double BandReferenceSolver::surfaceSpeed()
{
  // storedField(1) against storedField(2), read where they are.
  band_state::checkStoredField(2, steps_, source_.has_value());
  return surfaceSpeedOf(
      current_.size(), [&](size_t i) { return current_[i].x; }, [&](size_t i) { return next_[i].x; });
}

BandField BandReferenceSolver::field()
{
  // Beyond the band nothing moves: the far sides are the initial field's.
  BandField out = initial_;
  if (steps_ > 0) sweep<false>(&out.values());
  return out;
}

template <bool Collide>
void BandReferenceSolver::sweep(std::vector<float>* fieldOut)
{
  const BrickSet& bricks = *bricks_;
  const Extent3 e = bricks.cells();
  // A step updates the bricks that change; the field is read from all.
  std::vector<int32_t> all;
  if (!Collide) {
    all.resize(bricks.activeCount());
    for (size_t s = 0; s < all.size(); ++s) all[s] = int32_t(s);
  }
  const std::vector<int32_t>& work = Collide ? work_ : all;
  const glm::vec4* current = current_.data();
  glm::vec4* next = next_.data();
  const float decay = source_ ? source_->decay : 0.0f;
  const float scale = source_ ? source_->scale : 1.0f;
#pragma omp parallel for schedule(static)
  for (size_t w = 0; w < work.size(); ++w) {
    const size_t s = size_t(work[w]);
    const glm::ivec3 origin = brickEdge * bricks.brick(int32_t(s));
    const int32_t* around = neighbours_.data() + s * 27;
    if (frozen_.frozen(s)) {  // a step skips it; its field is what it froze with
      if constexpr (!Collide)
        for (int local = 0; local < brickCells; ++local) {
          const size_t i = s * brickCells + size_t(local);
          const glm::ivec3 c = bricks.cell(int32_t(s), local);
          if (e.contains(c.x, c.y, c.z)) (*fieldOut)[i] = frozenField_[i];
        }
      continue;
    }
    const bool held = !heldSlots_.empty() && heldSlots_[s] != 0;
    for (int local = 0; local < brickCells; ++local) {
      const size_t i = s * brickCells + size_t(local);
      const glm::ivec3 l(local % brickEdge, local / brickEdge % brickEdge, local / (brickEdge * brickEdge));
      const glm::ivec3 c = origin + l;
      if (!e.contains(c.x, c.y, c.z)) continue;
      const glm::vec4 own = current[i];
      // A held brick's cells, and cells that do not stream, pull from
      // themselves: f_i = w_i (rho* + 3 e_i . j*) sum to rho* with flux j*,
      // no f formed (as band_step.glsl).
      const auto [sum, J] = held || streams_[i] == 0 ? Pulled{own.x, glm::vec3(own.y, own.z, own.w)}
                                                     : pull(current, around, e, c, l, own);
      const auto [X, S] = withSource(sum, i, decay, scale);
      if constexpr (!Collide) {
        (*fieldOut)[i] = X;
      } else {
        const float omega = omegaPerCell_.empty() ? uniformOmega_ : omegaPerCell_[i];
        next[i] = glm::vec4(X + 0.5f * S, (1.0f - omega) * J);
      }
    }
  }
}

}  // namespace lbmshape
