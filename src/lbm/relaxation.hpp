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

namespace lbmshape::relaxation {

double tauFromGamma(double gamma);
double gammaFromTau(double tau);
inline double omegaFromGamma(double gamma) { return 1.0 / tauFromGamma(gamma); }

// Throws UsageError unless 0 < gamma <= parameter_bounds::maxGamma: tau inside BGK's
// linear stability range 1/2 < tau (omega < 2), and small enough for the
// lattice to diffuse (core/parameter_bounds.hpp). `what` names the option.
void checkGamma(double gamma, const char* what = "gamma");

}  // namespace lbmshape::relaxation
