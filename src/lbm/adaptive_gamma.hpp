// Per-cell diffusion coefficients for the anisotropic smoothing of section 5.1.
#pragma once

#include "lbmshape/shaders/adaptive_gamma_bounds.h"
#include "lbmshape/band/band_field.hpp"
#include "lbmshape/core/volume.hpp"

namespace lbmshape::adaptive_gamma {

// The range every per-cell gamma is clamped to, in voxels^2 per step
// (shaders/adaptive_gamma_bounds.h says why).
inline constexpr double lowest = ADAPTIVE_GAMMA_LOWEST;
inline constexpr double highest = ADAPTIVE_GAMMA_HIGHEST;

// The paper's rule, Eqs. 18-20: with |grad X| = 1 the step's change of X is
// gamma times the mean curvature, so kappa = (X(n+1) - X(n)) / gamma(n), and
// the next step uses gamma(n+1) = gamma0 + kappa, clamped to [lowest, highest].
// kappa is negative where the surface is convex (X is positive inside), so
// convex ridges diffuse less and concave creases more. Single precision, in
// the order of the step shaders, which apply the rule on the device
// (LatticeSolver::setPaperRule); the reference solvers call this.
Volume paperRule(const Volume& before, const Volume& after, const Volume& gammaUsed, double gamma0);

// lbmshape's feature-preserving rule, in the spirit of Perona-Malik: gamma
// falls where the surface bends sharply at the scale of the smoothing,
//     gamma = gamma0 / (1 + (kappa_s / kappaEdge)^2),
// with kappa_s the mean curvature (the Laplacian, |grad X| = 1) of a copy of
// the field already smoothed isotropically, where the noise is gone but the
// sharp edges are still sharp bends. Clamped to [lowest, gamma0].
Volume featurePreservingRule(const Volume& smoothed, double gamma0, double kappaEdge);
// Throws unless the rule can run with these: gamma0 as --gamma is checked
// (UsageError), kappaEdge positive (std::invalid_argument). Both rules above
// call it, and so do the devices' (BandVulkanSolver and VulkanSolver::
// setFeaturePreservingGamma; their shaders share feature_rule.glsl).
void checkFeatureRule(double gamma0, double kappaEdge);

// The mean curvature of a distance field by the 7-point Laplacian (zero-flux
// at the grid's faces, like the lattice's walls).
Volume laplacian(const Volume& field);

// The same three on the narrow band (the Laplacian reads the far value
// beyond the band's bricks, which no streaming cell is near).
BandField paperRule(const BandField& before, const BandField& after, const BandField& gammaUsed, double gamma0);
BandField featurePreservingRule(const BandField& smoothed, double gamma0, double kappaEdge);
BandField laplacian(const BandField& field);

}  // namespace lbmshape::adaptive_gamma
