// --steps auto, the default of denoise: how many steps a noisy surface
// needs. Noise decays fast under diffusion (a ripple of wavelength l like
// exp(-gamma (2 pi / l)^2 t)), the shape slowly (it moves by gamma kappa a
// step, kappa its curvature). So the surface's speed, the mean change of X
// a step over the cells the surface passes through, falls steeply while the
// noise goes and then levels off at the speed of the shape. The smoothing
// keeps the field of step n - 1 for the first step n whose speed is at
// least levelRatio times the step before's. The rule has no scale in it: it
// reads the noise off the field, whatever the mesh, its units or the size
// of its triangles. docs/denoising.md has the measurements that chose the
// constants.
#pragma once

#include <vector>

namespace lbmshape::smoothing_stop {

inline constexpr int fewestSteps = 2;
// At most the old fixed default, for which the narrow band's width is chosen.
inline constexpr int mostSteps = 7;
inline constexpr double levelRatio = 0.88;

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
// the first whose speed has levelled off; the smoothing then keeps the
// field of step n - 1.
inline bool levelledOff(int n, double previous, double speed)
{
  return n - 1 >= fewestSteps && speed >= levelRatio * previous;
}

}  // namespace lbmshape::smoothing_stop
