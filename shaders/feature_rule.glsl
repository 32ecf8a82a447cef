// lbmshape's feature-preserving rule, written once for the dense lattice's
// shader (lbm_feature_rule.comp) and the band's (band_feature_rule.comp);
// the CPU form, which the reference solvers apply, is
// adaptive_gamma::featurePreservingRule:
//     gamma = clamp(gamma0 / (1 + (kappa / kappaEdge)^2), lowest, gamma0),
// and omega = 1 / (3 gamma + 1/2), for four cells of Laplacian `kappa`.
// Cells beyond the grid (`outside`) get gamma0's omega.
vec4 featurePreservingOmega(vec4 kappa, bvec4 outside, float gamma0, float kappaEdge, float lowestGamma)
{
  const vec4 r = kappa / kappaEdge;
  const vec4 gamma = mix(clamp(gamma0 / (1.0 + r * r), lowestGamma, gamma0), vec4(gamma0), outside);
  return 1.0 / (3.0 * gamma + 0.5);
}
