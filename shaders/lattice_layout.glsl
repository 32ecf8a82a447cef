// The lattice's memory layout and grid constants, shared by every lattice
// shader; src/lbm/lattice_memory.hpp describes the same layout on the host.
//
// Cells are x-fastest, rows padded to ROW cells (a multiple of 4), taken four
// at a time: block b is cells 4b..4b+3, one vec4. The 19 directions fall into
// nine groups by the row they pull from, (e_y, e_z). Each group is one
// contiguous array in which every block keeps its directions side by side:
//     vec4 index of (block b, direction i) in a lattice copy:
//         BLOCKS groupStart[g] + b groupSize[g] + slotOf[i],   g = groupOf[i]
// So a step reads nine streams (one per neighbouring row) and writes nine, and
// uses every cache line it touches whole. (One array per direction, 19 read
// and 19 write streams, ran at a third of the speed on lavapipe on an AMD EPYC:
// docs/performance.md.) A bounce-back at a wall is only another index into
// the same copy.

layout(constant_id = 2) const int NX = 4;  // constant 1 is unused
layout(constant_id = 3) const int NY = 1;
layout(constant_id = 4) const int NZ = 1;
layout(constant_id = 5) const int ROW = 4;
layout(constant_id = 6) const float W_REST = 1.0 / 3.0;
layout(constant_id = 7) const float W_AXIAL = 1.0 / 18.0;
layout(constant_id = 8) const float W_DIAGONAL = 1.0 / 36.0;
layout(constant_id = 9) const int BLOCKS = 16;  // of the grid, rounded up to a multiple of 16
const int PLANE = ROW * NY;
const int GROUPS = 9;

// The velocities in the order of src/lbm/d3q19.hpp, and the row groups of
// src/lbm/lattice_memory.hpp: (0,0) {0,1,2}, (1,0) {3,7,10}, (-1,0) {4,8,9},
// (0,1) {5,11,14}, (0,-1) {6,12,13}, (1,1) {15}, (-1,-1) {16}, (1,-1) {17},
// (-1,1) {18}.
const ivec3 velocity[19] = ivec3[](
    ivec3(0, 0, 0),
    ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0), ivec3(0, 0, 1), ivec3(0, 0, -1),
    ivec3(1, 1, 0), ivec3(-1, -1, 0), ivec3(1, -1, 0), ivec3(-1, 1, 0),
    ivec3(1, 0, 1), ivec3(-1, 0, -1), ivec3(1, 0, -1), ivec3(-1, 0, 1),
    ivec3(0, 1, 1), ivec3(0, -1, -1), ivec3(0, 1, -1), ivec3(0, -1, 1));
const int groupOf[19] = int[](0, 0, 0, 1, 2, 3, 4, 1, 2, 2, 1, 3, 4, 4, 3, 5, 6, 7, 8);
const int slotOf[19] = int[](0, 1, 2, 0, 0, 0, 0, 1, 1, 2, 2, 1, 1, 2, 2, 0, 0, 0, 0);
const int groupSize[9] = int[](3, 3, 3, 3, 3, 1, 1, 1, 1);
const int groupStart[9] = int[](0, 3, 6, 9, 12, 15, 16, 17, 18);

int linearIndex(ivec3 c) { return c.x + ROW * (c.y + NY * c.z); }
bool isRealCell(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(NX, NY, NZ))); }
float weight(int i) { return i == 0 ? W_REST : (i <= 6 ? W_AXIAL : W_DIAGONAL); }

// vec4 index of block b's direction i within its group, and within the copy.
int indexInGroup(int b, int i) { return b * groupSize[groupOf[i]] + slotOf[i]; }
int latticeIndex(int b, int i) { return BLOCKS * groupStart[groupOf[i]] + indexInGroup(b, i); }
