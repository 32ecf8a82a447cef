// The lattice's memory layout and grid constants, shared by every lattice
// shader; src/lbm/lattice_memory.hpp describes the same layout on the host.
//
// Cells are x-fastest, rows padded to ROW cells (a multiple of 4), taken four
// at a time: block b is cells 4b..4b+3, one vec4. The 19 directions fall into
// nine groups by the row they pull from, (e_y, e_z). Each group is one
// contiguous array in which every block keeps its directions side by side:
//     vec4 index of (block b, direction e) in a lattice copy:
//         BLOCKS GROUP_START(g) + b GROUP_SIZE(g) + SLOT(e_x),   g = ROW_GROUP(e_y, e_z)
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

// The 19 velocities (I, EX, EY, EZ) in the order of src/lbm/d3q19.hpp; M is
// applied to each. Everything below is written as macros of these literals
// so that glslang folds it to constants: indexing constant arrays instead cost
// lavapipe ten times longer pipeline creation.
#define FOR_EACH_DIRECTION(M)                                                           \
  M(0, 0, 0, 0)                                                                         \
  M(1, 1, 0, 0) M(2, -1, 0, 0) M(3, 0, 1, 0) M(4, 0, -1, 0) M(5, 0, 0, 1) M(6, 0, 0, -1) \
  M(7, 1, 1, 0) M(8, -1, -1, 0) M(9, 1, -1, 0) M(10, -1, 1, 0)                          \
  M(11, 1, 0, 1) M(12, -1, 0, -1) M(13, 1, 0, -1) M(14, -1, 0, 1)                       \
  M(15, 0, 1, 1) M(16, 0, -1, -1) M(17, 0, 1, -1) M(18, 0, -1, 1)

#define WEIGHT(EX, EY, EZ) \
  ((EX) * (EX) + (EY) * (EY) + (EZ) * (EZ) == 0 ? W_REST : (EX) * (EX) + (EY) * (EY) + (EZ) * (EZ) == 1 ? W_AXIAL : W_DIAGONAL)

// The row groups of src/lbm/lattice_memory.hpp, numbered by the row (e_y, e_z)
// they pull from: (0,0) 0, (1,0) 1, (-1,0) 2, (0,1) 3, (0,-1) 4, (1,1) 5,
// (-1,-1) 6, (1,-1) 7, (-1,1) 8. The first five hold three directions (slot
// 0, 1, 2 for e_x = 0, 1, -1), the diagonal rows one.
#define ROW_GROUP(EY, EZ)                                          \
  ((EZ) == 0   ? ((EY) == 0 ? 0 : (EY) == 1 ? 1 : 2)               \
   : (EY) == 0 ? ((EZ) == 1 ? 3 : 4)                               \
   : (EY) == (EZ) ? ((EY) == 1 ? 5 : 6)                            \
                  : ((EY) == 1 ? 7 : 8))
#define SLOT(EX) ((EX) == 0 ? 0 : (EX) == 1 ? 1 : 2)
#define GROUP_SIZE(G) ((G) < 5 ? 3 : 1)
#define GROUP_START(G) ((G) < 5 ? 3 * (G) : 10 + (G))  // directions in the groups before G

// vec4 index of block B's direction (EX, EY, EZ) within its group, and within
// the whole lattice copy.
#define INDEX_IN_GROUP(B, EX, EY, EZ) ((B) * GROUP_SIZE(ROW_GROUP(EY, EZ)) + SLOT(EX))
#define LATTICE_INDEX(B, EX, EY, EZ) (BLOCKS * GROUP_START(ROW_GROUP(EY, EZ)) + INDEX_IN_GROUP(B, EX, EY, EZ))

int linearIndex(ivec3 c) { return c.x + ROW * (c.y + NY * c.z); }
bool isRealCell(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(NX, NY, NZ))); }
