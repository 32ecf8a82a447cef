// The range every per-cell gamma is kept in, in voxels^2 per step: one
// definition for the step shaders, which apply the paper's anisotropic rule
// on the device, and for src/lbm/adaptive_gamma.hpp, which applies both
// per-cell rules on the CPU. Below the lower end, tau = 3 gamma + 1/2 would
// approach the BGK stability limit 1/2 (0.01 keeps omega <= 1.89); above the
// upper end, one step would have to carry the field farther than the
// lattice's one-cell links can (a diffusion length sqrt(2 gamma) of 1.4
// voxels at 1.0). docs/denoising.md explains both.
#ifndef LBMSHAPE_ADAPTIVE_GAMMA_BOUNDS_H
#define LBMSHAPE_ADAPTIVE_GAMMA_BOUNDS_H

#define ADAPTIVE_GAMMA_LOWEST 0.01
#define ADAPTIVE_GAMMA_HIGHEST 1.0

#endif
