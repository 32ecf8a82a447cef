// The D3Q19 lattice: 19 discrete velocities (rest, 6 axial, 12 planar
// diagonals) and their weights. shaders/lattice_layout.glsl lists the same
// velocities in the same order (and lattice.glsl's PULL_ALL spells them out);
// the GPU-versus-reference tests fail if the two ever differ.
#pragma once

#include <array>

namespace lbmshape::d3q19 {

inline constexpr int Q = 19;

struct Velocity {
  int x, y, z;
};

inline constexpr std::array<Velocity, Q> velocities = {{
    {0, 0, 0},  {1, 0, 0},   {-1, 0, 0},  {0, 1, 0},  {0, -1, 0}, {0, 0, 1},   {0, 0, -1},
    {1, 1, 0},  {-1, -1, 0}, {1, -1, 0},  {-1, 1, 0}, {1, 0, 1},  {-1, 0, -1}, {1, 0, -1},
    {-1, 0, 1}, {0, 1, 1},   {0, -1, -1}, {0, 1, -1}, {0, -1, 1},
}};

// Weights of the equilibrium f_i^eq = w_i X: rest 1/3, axial 1/18, diagonal 1/36.
// 1/3, 1/18 and 1/36 rounded to fp32 sum to 1 + 1.5e-8, and that excess is
// multiplied into the total of X at every collision: 1e-5 lost conservation
// per 1000 steps. So the weights are fp32 values that sum to exactly 1: the
// diagonal and axial ones on grids (2^-27, 2^-26) fine enough that the rest
// weight 1 - 6 w1 - 12 w2 is itself an fp32 number. Each differs from its
// ideal value by less than 1e-8.
inline constexpr float diagonalWeight = float(static_cast<long>((1 << 27) / 36.0 + 0.5)) / float(1 << 27);
inline constexpr float axialWeight = float(static_cast<long>((1 << 26) / 18.0 + 0.5)) / float(1 << 26);
inline constexpr float restWeight = 1.0f - 6.0f * axialWeight - 12.0f * diagonalWeight;
static_assert(double(restWeight) + 6.0 * double(axialWeight) + 12.0 * double(diagonalWeight) == 1.0,
              "D3Q19 weights must sum to exactly one in fp32");

constexpr float weight(int i) { return i == 0 ? restWeight : (i <= 6 ? axialWeight : diagonalWeight); }

// Velocities come in opposite pairs (1,2), (3,4), ...: bounce-back swaps them.
constexpr int opposite(int i) { return i == 0 ? 0 : ((i % 2) ? i + 1 : i - 1); }

// The lattice speed of sound squared: sum_i w_i e_ix^2. It fixes the diffusion
// coefficient of the BGK scheme, gamma = c_s^2 (tau - 1/2).
inline constexpr double soundSpeedSquared = 1.0 / 3.0;

}  // namespace lbmshape::d3q19
