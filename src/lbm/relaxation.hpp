// Conversions between the diffusion coefficient gamma (voxels^2 per step) that
// users set and the BGK relaxation time tau that the lattice uses.
//
// The Chapman-Enskog expansion of the BGK scheme with f_eq = w_i X on D3Q19
// gives dX/dt = c_s^2 (tau - 1/2) Laplacian(X) with c_s^2 = 1/3, so
//     gamma = (tau - 1/2) / 3,   tau = 3 gamma + 1/2.
// The paper's Eq. 16 writes gamma = 4/9 (2 tau - 1), which is 8/3 times larger;
// docs/lattice-theory.md explains the difference and the diffusion test in
// tests/ measures which one the lattice obeys.
#pragma once

#include <cmath>
#include <string_view>

#include "lbmshape/core/parameter_bounds.hpp"

namespace lbmshape::relaxation {

double tauFromGamma(double gamma);
double gammaFromTau(double tau);
inline double omegaFromGamma(double gamma) { return 1.0 / tauFromGamma(gamma); }
// omega of a per-cell gamma, in single precision as the step shaders compute
// it under the paper's rule: a per-cell gamma gives the same omega whether
// the host or the device converts it.
inline float singlePrecisionOmega(float gamma) { return 1.0f / (3.0f * gamma + 0.5f); }

// What checkGamma accepts, without a message: for loops over every cell.
inline bool acceptableGamma(double gamma)
{
  return std::isfinite(gamma) && gamma > 0.0 && gamma <= parameter_bounds::maxGamma &&
         float(omegaFromGamma(gamma)) < 2.0f;  // omega in fp32 (checkGamma says why)
}

// Throws UsageError unless 0 < gamma <= parameter_bounds::maxGamma: tau inside BGK's
// linear stability range 1/2 < tau (omega < 2), and small enough for the
// lattice to diffuse (core/parameter_bounds.hpp). `what` names the value in
// the message; by default it is the gamma parameter, named only when the
// check fails (solvers check every cell of a per-cell gamma).
void checkGamma(double gamma, std::string_view what = {});

// How far `steps` steps started in equilibrium (f_i = w_i X, as every run
// starts) miss the smoothing of the diffusion equation, as a fraction of it:
// the variance of any pulse grows by 2 gamma n (1 + startUpError). The first
// step always spreads by 1/3 voxel^2, whatever tau is, and the excess over
// 2 gamma decays like (1 - 1/tau)^t (docs/lattice-theory.md derives it):
//     startUpError = (1/3 - 2 gamma) tau (1 - (1 - 1/tau)^n) / (2 gamma n).
// Negative: less smoothing than gamma * n promises (gamma above 1/6).
double startUpError(double gamma, long steps);

// Beyond this |startUpError| the commands warn that the run is outside the
// range where the scheme follows the diffusion equation it stands for.
inline constexpr double accurateStartUpError = 0.10;

// That warning, on stderr, naming gamma and what to change; silent inside
// the accurate range.
void warnIfInaccurate(double gamma, long steps);

}  // namespace lbmshape::relaxation
