// --steps auto, the default of denoise: how many steps a noisy surface
// needs. Noise decays fast under diffusion (a ripple of wavelength l like
// exp(-gamma (2 pi / l)^2 t)), the shape slowly (it moves by gamma kappa a
// step, kappa its curvature). So the surface's speed, the spread of the
// change of X a step over the cells the surface passes through (its mean,
// a uniform move that keeping the volume undoes, left out:
// lbm/surface_change.hpp), falls steeply while the noise goes and then
// levels off at the speed of the shape's uneven motion. The smoothing
// keeps the field of step n - 1 for the first step n whose speed is at
// least levelRatio times the step before's. The rule has no scale in it: it
// reads the noise off the field, whatever the mesh, its units or the size
// of its triangles. docs/denoising.md has the measurements that chose the
// constants.
#pragma once

#include <vector>

namespace lbmshape::smoothing_stop {

// Three, not two: at two a lightly noisy surface was kept where the third
// step's speed read at the ratio itself (the fandisk at 0.25 voxel of
// noise with seed 3: 0.852), and low-poly inputs, whose noise lies on
// their large triangles and fades slowly, stopped there too; measured on
// 135 noisy cases against OpenVDB (docs/denoising.md, "How many steps"),
// three fewest lost none that two won and won three more.
inline constexpr int fewestSteps = 3;
// At most the old fixed default, for which the narrow band's width is chosen.
inline constexpr int mostSteps = 7;
inline constexpr double levelRatio = 0.85;
// Voxels a step below which the surface counts as still: a clean sphere's
// faceting moves it by 0.002-0.005 voxel a step, where a ratio of two
// speeds says nothing (the slowest a noisy shared mesh was read at before
// the rule stopped, 0.007 voxel, is above it).
inline constexpr double stillSpeed = 0.005;

// The field's decay cannot tell noise that lies on an input's own triangles
// from its shape where the triangles are several voxels long: moved along
// the normals, each triangle is tilted whole, the noise has the wavelength
// of two triangles and fades as slowly as the shape (the shared Eight's
// speeds fall by the same ratios clean and with noise of a voxel). Its
// amplitude shows on the mesh (analysis/normal_noise.hpp): the smoothing
// then runs at least until its spread, the standard deviation of the
// Gaussian it amounts to, reaches noiseMargin times that amplitude, plain
// (twicing would give back the slow noise it took). 1.1 is the least that
// won every case it was chosen on against OpenVDB (docs/denoising.md,
// "The noise's amplitude"): the Eight at 1 voxel reads 1.03, which the
// fewest steps' spread (sqrt(1.13) = 1.06 voxels) already covers at 1.0.
inline constexpr double noiseMargin = 1.1;

// The fewest steps at `gamma` whose spread reaches noiseMargin times the
// noise's amplitude (voxels), at most mostSteps.
int fewestStepsForNoise(double amplitudeVoxels, double gamma);

// The surface's speed from one field to the next, for the grid (--dense),
// which reads its fields back: the measure of lbm/surface_change.hpp (the
// band computes it in place, BandSolver::surfaceSpeed), with only the cells
// of the field before where |X before| < 1 voxel kept, one bit a cell
// saying which they are: about a sixth of the memory of a whole field.
class SurfaceSpeed {
public:
  explicit SurfaceSpeed(const std::vector<float>& start) { remember(start); }
  // The speed from the last field to `field`, which becomes the last.
  double advance(const std::vector<float>& field);

private:
  void remember(const std::vector<float>& field);
  std::vector<bool> onSurface_;  // per cell of the last field
  std::vector<float> surface_;   // X of those cells, in order
};

// Whether step n, of speed `speed` after a step of speed `previous`, is
// the first whose speed has levelled off (or the surface stands still);
// the smoothing then keeps the field of step n - 1.
inline bool levelledOff(int n, double previous, double speed)
{
  return n - 1 >= fewestSteps && (speed >= levelRatio * previous || speed < stillSpeed);
}

}  // namespace lbmshape::smoothing_stop
