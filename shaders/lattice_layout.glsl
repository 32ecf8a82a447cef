// The lattice's memory layout and grid constants, shared by every lattice
// shader; src/lbm/lattice_memory.cpp computes the same layout on the host.
//
// Structure of arrays: one array of cells per direction, cells x-fastest,
// rows padded to ROW cells (a multiple of 4, so four cells x0..x0+3 with
// x0 % 4 == 0 are one vec4). Opposite directions share a buffer: pair p holds
// direction 2p-1 at offset 0 and direction 2p at offset DIRECTION_FLOATS
// (pair 0 holds the rest direction alone). A wall bounces f*_opp(i) of the
// cell itself back as f_i, so keeping i and opp(i) in one buffer turns every
// wall into a choice of index, with no extra fetch and no branch.
//     cell (x, y, z) of direction i: pair (i + 1) / 2, float
//     offset(i) + x + ROW (y + NY z),  offset(i) = i even and > 0 ? DIRECTION_FLOATS : 0

layout(constant_id = 2) const int NX = 4;  // constant 1 is unused
layout(constant_id = 3) const int NY = 1;
layout(constant_id = 4) const int NZ = 1;
layout(constant_id = 5) const int ROW = 4;
layout(constant_id = 6) const float W_REST = 1.0 / 3.0;
layout(constant_id = 7) const float W_AXIAL = 1.0 / 18.0;
layout(constant_id = 8) const float W_DIAGONAL = 1.0 / 36.0;
layout(constant_id = 9) const int DIRECTION_FLOATS = 4;  // a multiple of 64
const int PLANE = ROW * NY;

int linearIndex(ivec3 c) { return c.x + ROW * (c.y + NY * c.z); }
bool isRealCell(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(NX, NY, NZ))); }

// The velocities in the order of src/lbm/d3q19.hpp.
const ivec3 velocity[19] = ivec3[](
    ivec3(0, 0, 0),
    ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0), ivec3(0, 0, 1), ivec3(0, 0, -1),
    ivec3(1, 1, 0), ivec3(-1, -1, 0), ivec3(1, -1, 0), ivec3(-1, 1, 0),
    ivec3(1, 0, 1), ivec3(-1, 0, -1), ivec3(1, 0, -1), ivec3(-1, 0, 1),
    ivec3(0, 1, 1), ivec3(0, -1, -1), ivec3(0, 1, -1), ivec3(0, -1, 1));

float weight(int i) { return i == 0 ? W_REST : (i <= 6 ? W_AXIAL : W_DIAGONAL); }
