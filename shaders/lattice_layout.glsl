// The lattice's memory layout and grid constants, shared by every lattice
// shader; src/lbm/lattice_memory.cpp computes the same layout on the host.
//
// Structure of arrays: one buffer per direction. Around the NX x NY x NZ cells
// lie ghost rows (y = -1, y = NY) and ghost planes (z = -1, z = NZ). A ghost
// slot of direction i holds what the wall bounces back into the real cell
// r = ghost + e_i, so the pull needs no wall tests in y and z. Rows are padded
// to ROW >= NX + 1 cells, a multiple of 4, so four cells x0..x0+3 with
// x0 % 4 == 0 are one vec4; the padding and 4 leading and trailing floats keep
// the x-shifted fetches of the first and last blocks inside the buffer (the
// walls in x are handled in the pull itself, see lattice.glsl).
//     linear(x, y, z) = 4 + x + ROW (y + 1) + PLANE (z + 1),  PLANE = ROW (NY + 2)

layout(constant_id = 2) const int NX = 4;
layout(constant_id = 3) const int NY = 1;
layout(constant_id = 4) const int NZ = 1;
layout(constant_id = 5) const int ROW = 8;
layout(constant_id = 6) const float W_REST = 1.0 / 3.0;
layout(constant_id = 7) const float W_AXIAL = 1.0 / 18.0;
layout(constant_id = 8) const float W_DIAGONAL = 1.0 / 36.0;
const int PLANE = ROW * (NY + 2);

int linearIndex(ivec3 c) { return 4 + c.x + ROW * (c.y + 1) + PLANE * (c.z + 1); }
bool isRealCell(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(NX, NY, NZ))); }

// The velocities in the order of src/lbm/d3q19.hpp.
const ivec3 velocity[19] = ivec3[](
    ivec3(0, 0, 0),
    ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0), ivec3(0, 0, 1), ivec3(0, 0, -1),
    ivec3(1, 1, 0), ivec3(-1, -1, 0), ivec3(1, -1, 0), ivec3(-1, 1, 0),
    ivec3(1, 0, 1), ivec3(-1, 0, -1), ivec3(1, 0, -1), ivec3(-1, 0, 1),
    ivec3(0, 1, 1), ivec3(0, -1, -1), ivec3(0, 1, -1), ivec3(0, -1, 1));

float weight(int i) { return i == 0 ? W_REST : (i <= 6 ? W_AXIAL : W_DIAGONAL); }
