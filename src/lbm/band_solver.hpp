// The lattice Boltzmann scheme on the narrow band (band/), stored as four
// moments a cell instead of 19 distributions: the regularised form of the
// same D3Q19 scheme (lattice_solver.hpp). docs/lattice-theory.md derives it.
//
// After collision a cell keeps rho* = X + S/2 and the flux j* = (1 - omega) J,
// the zeroth and first moments of BGK's post-collision distributions (with
// sum_i f_i = X - S/2, BGK's f* sums to X - S/2 + omega S/2 + (1 - omega/2) S
// = X + S/2, whatever omega), from which every distribution follows:
//     f*_i = w_i (rho* + 3 e_i . j*).
// A step pulls f_i(x) = f*_i(x - e_i) from the neighbours' moments, sums
// X = sum_i f_i (+ S/2, solved exactly for S = A - c X, as on the grid) and
// J = sum_i e_i f_i, and collides. This is BGK with the distributions'
// higher moments filtered out at every collision: the same scheme exactly
// at omega = 1 (tau = 1), and the same diffusion coefficient c_s^2 (tau -
// 1/2) otherwise; 16 bytes a cell a copy instead of 76.
//
// Cells with |X| < streamingHalfWidth at initialisation stream; the others,
// near the band's edge, are held: they pull from themselves (no exchange
// with their neighbours), so they keep their value, or follow only the
// source. Streaming cells next to them see a fixed boundary value. Cells at
// the grid's faces bounce back, as on the grid.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "lbmshape/band/band_field.hpp"
#include "lbmshape/lbm/adaptive_gamma.hpp"
#include "lbmshape/lbm/stepping_solver.hpp"
#include "lbmshape/surface/surface_pieces.hpp"

namespace lbmshape {

// S = scale * base - decay * X in every cell of the band (LinearSource).
struct BandSource {
  BandField base;
  float decay = 0.0f;
  float scale = 1.0f;
};

// The kind of run a band solver is made for: a device solver prepares its
// pipeline at set-up (BandVulkanSolver: one per kind), and prepares
// another kind's at its first use.
struct BandRunKind {
  bool source = false;     // a morph's source term (setSource)
  bool paperRule = false;  // the paper's anisotropic rule (setPaperRule)
};

// 1 for each stored cell inside the grid with |X| < halfWidth, else 0.
std::vector<uint8_t> streamingCells(const BandField& field, double halfWidth);

class BandSolver : public SteppingSolver {
public:
  virtual const BrickSet& bricks() const = 0;

  virtual void setUniformGamma(double gamma) = 0;
  virtual void setGammaPerCell(const BandField& gamma) = 0;
  // The paper's anisotropic rule, as LatticeSolver::setPaperRule describes.
  virtual void setPaperRule(double gamma0) = 0;
  // lbmshape's feature-preserving rule (adaptive_gamma::featurePreservingRule)
  // on the field now, as gamma per cell. Here the field is read back and
  // the rule runs on the host (the CPU reference); BandVulkanSolver runs it
  // on the device, reading nothing back, with the older stored copy as its
  // scratch: there storedField(2), surfaceSpeed() and previousField() need
  // one more step after it.
  virtual void setFeaturePreservingGamma(double gamma0, double kappaEdge)
  {
    setGammaPerCell(adaptive_gamma::featurePreservingRule(field(), gamma0, kappaEdge));
  }
  // The Vulkan solver lets the host's copy of the source's base go after
  // the first step (unless the field is held for a restart): a later
  // initialize() needs setSource() again.
  virtual void setSource(std::optional<BandSource> source) = 0;
  // The source's decay and scale, its base kept (LatticeSolver's).
  virtual void setSourceStrength(float decay, float scale) = 0;
  // Bricks held whole from the next step on: one BrickMotion a brick slot
  // (lbm/frozen_bricks.hpp); empty for none. Held (1): every cell of the
  // brick pulls from itself whatever initialize()'s flags say; the steps
  // and field passes read nothing around them, so they cost a fraction of
  // a streaming brick's: a morph holds the bricks its moving front is far
  // from. Frozen (2): from the next step on no step or field pass touches
  // the brick, which keeps the field it froze with; when it is set to
  // anything else it catches up, in one held step, with the steps it
  // missed. The caller freezes only bricks that no streaming brick reads
  // (none of their 26 neighbours streams meanwhile), under a uniform
  // omega and a source whose scale is its decay (else the step throws
  // std::logic_error). Kept across initialize() and restart(); not with
  // the feature rule.
  virtual void setHeldBricks(std::vector<uint8_t> heldPerSlot) = 0;

  // Restart from field X, every cell at equilibrium (after setSource); the
  // cells flagged in `streams` (one byte a stored cell) stream, the others
  // are held. The solver keeps `field` until its first step (field() is
  // it until then): a caller done with it moves it in, and the band is not
  // held twice.
  virtual void initialize(BandField field, std::vector<uint8_t> streams) = 0;
  // The same with the cells within `streamingHalfWidth` of the surface streaming.
  void initialize(BandField field, double streamingHalfWidth)
  {
    std::vector<uint8_t> streams = streamingCells(field, streamingHalfWidth);
    initialize(std::move(field), std::move(streams));
  }
  // Keeps the field that the next initialize() gets past its first step,
  // for one restart(): a smoothing that first runs a copy of itself (the
  // feature rule's edge finding) then holds the band once, not twice.
  virtual void holdFieldForRestart() = 0;
  // Starts again from the field the last initialize() got, with the same
  // streaming cells, under the gamma set now: what initialize() with that
  // field and those streams would do. Throws std::logic_error unless the
  // field was held (holdFieldForRestart()) or no step has let it go, and
  // when a source was set or cleared since (the cells a step updates
  // depend on it).
  virtual void restart() = 0;

  // The field X after the steps taken so far, on the same bricks; beyond
  // them (far value and sides) as the field initialize() was given.
  virtual BandField field() = 0;
  // The same into `out`, whose memory is used again where it has this
  // band's shape (a morph's frames: no new pages to fault in and clear).
  virtual void fieldInto(BandField& out) { out = field(); }
  // fieldInto(out), then step(1) under `next` (LatticeSolver's).
  virtual void fieldIntoThenStep(BandField& out, std::optional<SourceStrength> next)
  {
    fieldInto(out);
    if (next) setSourceStrength(next->decay, next->scale);
    step(1);
  }
  // X one step before that, as LatticeSolver::previousField.
  virtual BandField previousField() = 0;
  // X one or two steps before the last (`back`), read from what the two
  // copies of the moments keep: a collision stores rho* = X + S/2, so
  // without a source each copy holds the X its collision had. No pass over
  // the band, only a copy of one float a cell. Throws std::logic_error with
  // a source or before `back` steps.
  virtual BandField storedField(int back) = 0;
  // How far the surface moved from storedField(2) to storedField(1)
  // (lbm/surface_change.hpp), under the same conditions, without reading
  // either back: the CPU reference reads its moments in place, the Vulkan
  // solver sums on the device and reads back three sums a row of a brick.
  virtual double surfaceSpeed() = 0;

  // The pieces of the surface X = request.isovalue now
  // (surface/surface_pieces.hpp), what a morph's frame needs in place of
  // the field, with what the request asks: the error near the source's
  // base (none without a source), the values at its probes. Here
  // listSurfacePieces() of field(), the reference; BandVulkanSolver lists
  // them on the device and reads back only them.
  virtual SurfacePieces surfacePieces(const SurfaceRequest& request)
  {
    const BandField now = field();
    return listSurfacePieces(now, request, sourceBase());
  }
  // surfacePieces(), then step(1) under `next` (fieldIntoThenStep's).
  virtual SurfacePieces surfacePiecesThenStep(const SurfaceRequest& request, std::optional<SourceStrength> next)
  {
    SurfacePieces pieces = surfacePieces(request);
    if (next) setSourceStrength(next->decay, next->scale);
    step(1);
    return pieces;
  }

protected:
  // The source's base where the solver keeps it on the host, else null.
  virtual const BandField* sourceBase() const { return nullptr; }
};

}  // namespace lbmshape
