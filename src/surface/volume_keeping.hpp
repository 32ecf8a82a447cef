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

#include "lbmshape/band/band_field.hpp"
#include "lbmshape/core/volume.hpp"
#include "lbmshape/mesh/triangle_mesh.hpp"
#include "lbmshape/sdf/grid_frame.hpp"

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

// The volume kept above is the field's, counted on its cells. The triangles
// of its zero level (marching cubes) are chords of the curved surface and
// enclose a little less, whatever the smoothing did: on the shared meshes
// 0.03-0.3 % at --res 128 and 1-3.6 % at 48 (docs/denoising.md, "Keeping
// the volume"). What it takes to give them that volume:

// How much more the zero level `level` of `field` encloses per voxel that
// the field is shifted by (world units of volume per voxel): a vertex
// moves along its normal by the shift over |grad X| there (a smoothed
// field is not a distance everywhere: |grad X| falls below 1 where thin
// parts thin out), carrying a third of the area of its triangles.
double volumePerShift(const Volume& field, const GridFrame& frame, const TriangleMesh& level);
double volumePerShift(const BandField& field, const GridFrame& frame, const TriangleMesh& level);

// The further shift, in voxels, that brings a zero level enclosing
// `volume` to `wanted` at `perShift` (volumePerShift). Zero where perShift
// is not positive, and where the two differ by more than `mostRelative` of
// `wanted`: that much is not the triangles' bias (an input counted twice
// where it overlaps itself, say).
double meshVolumeShift(double wanted, double volume, double perShift, double mostRelative);

}  // namespace lbmshape
