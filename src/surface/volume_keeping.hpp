// Smoothing by mean curvature shrinks a surface: every convex part moves
// inwards by about gamma * kappa a step, so a denoise loses volume (the
// Armadillo at 128: 4 % in 7 steps) and lies inside the clean shape it
// should recover. denoise keeps the input's volume by shifting the smoothed
// field by one constant, a level-set offset: the shape the smoothing gave,
// moved out along its normals by the same distance everywhere, which changes
// neither its normals nor its smoothness.
//
// The volume a field encloses is counted in voxels with a linear ramp
// across the surface, V(X) = sum over cells of clamp(X + 1/2, 0, 1): exact
// for a plane at any position and orientation where X is a distance (the
// ramp's error is odd about the surface), and the same estimate is applied
// to the field before and after smoothing, so what bias curvature gives it
// cancels. docs/denoising.md has the measurements.
#pragma once

#include "band/band_field.hpp"
#include "core/volume.hpp"

namespace lbmshape {

// V(X + shift), in voxels. On the band: over the stored cells inside the
// grid; the cells beyond the band are the same before and after smoothing,
// so they are left out of both counts.
double enclosedVoxels(const Volume& field, double shift = 0.0);
double enclosedVoxels(const BandField& field, double shift = 0.0);

// The shift d, in voxels, for which V(field + d) = voxels (Newton's method
// on the piecewise-linear V), bounded to [-maxShift, maxShift].
double volumeKeepingShift(const Volume& field, double voxels, double maxShift);
double volumeKeepingShift(const BandField& field, double voxels, double maxShift);

// Adds d to every value of the field (on the band: the stored values).
void shiftField(Volume& field, double d);
void shiftField(BandField& field, double d);

}  // namespace lbmshape
