// Shared by the narrow band's shaders (band_step.comp, band_feature_rule.comp):
// the push constants and the bindings they read, this invocation's brick
// and row, and where a row of the brick, or of a brick beside it, lies.
// A workgroup is one brick; an invocation one of its rows of eight cells.
#include "band_interface.h"

layout(local_size_x = BAND_WORKGROUP_SIZE) in;

layout(push_constant) uniform Parameters { BAND_STEP_PARAMETERS(BAND_DECLARE_FIELD) } p;

layout(set = 0, binding = BAND_BINDING_MOMENTS) uniform samplerBuffer moments;
layout(set = 0, binding = BAND_BINDING_NEIGHBOURS) uniform isamplerBuffer neighbours;
layout(set = 0, binding = BAND_BINDING_ORIGINS) uniform isamplerBuffer origins;
layout(set = 0, binding = BAND_BINDING_WORK) uniform isamplerBuffer work;
layout(set = 0, binding = BAND_BINDING_OMEGA_OUT, std430) writeonly buffer OmegaPool { vec4 v[]; } omegaPools[BAND_MAX_FIELD_POOLS];

int slot, y, z;  // this invocation's brick and row
ivec3 origin;    // the brick's first cell

// vec4 index of moment `m` of row (yy, zz), half hh, of brick s.
int momentAt(int s, int m, int yy, int zz, int hh) { return BAND_MOMENT_INDEX(s, m, zz * 8 + yy, hh); }
// The slots of the bricks at (-1, dy, dz), (0, dy, dz) and (1, dy, dz) from
// this one (-1: none), in one fetch: on lavapipe a fetch per row and per row
// end took a step a sixth of its time.
ivec3 rowBricks(int dy, int dz) { return texelFetch(neighbours, slot * 9 + (dy + 1) + 3 * (dz + 1)).xyz; }
vec4 moment(int index) { return texelFetch(moments, index); }

bvec4 both(bvec4 a, bvec4 b) { return bvec4(uvec4(a) & uvec4(b)); }

// The buffers of a float a cell that the shaders write through pools (the
// field, the omega buffer): this brick's pool, and where vec4 `cells` (the
// index in the per-cell arrays) lies in it. Every pool holds whole bricks,
// so a workgroup writes to one pool (the index is dynamically uniform).
const int VEC4S_PER_BRICK = 128;  // 512 cells, four a vec4
int perCellPool() { return slot / p.slotsPerFieldPool; }
int inPerCellPool(int cells) { return cells - perCellPool() * p.slotsPerFieldPool * VEC4S_PER_BRICK; }

// Stores vec4 `cells` of this brick in the omega buffer.
void storePerCell(int cells, vec4 value) { omegaPools[perCellPool()].v[inPerCellPool(cells)] = value; }

// Where row (yy, zz) of this brick's coordinates (-1 .. 8) lies: the slot
// and the row within it, and the slots of the bricks before and after that
// one along x (-1: none); `valid` false where it is beyond the grid's faces
// or in a brick outside the band, and then the invocation's own row stands
// in for it.
struct RowPlace {
  int slot, ly, lz, left, right;
  bool valid;
};

RowPlace rowPlace(int yy, int zz)
{
  RowPlace r;
  const ivec3 bricks = rowBricks(yy < 0 ? -1 : (yy > 7 ? 1 : 0), zz < 0 ? -1 : (zz > 7 ? 1 : 0));
  const int rowSlot = bricks.y;
  r.left = bricks.x;
  r.right = bricks.z;
  r.valid = origin.y + yy >= 0 && origin.y + yy < p.ny && origin.z + zz >= 0 && origin.z + zz < p.nz && rowSlot >= 0;
  r.slot = r.valid ? rowSlot : slot;
  r.ly = r.valid ? yy & 7 : y;
  r.lz = r.valid ? zz & 7 : z;
  return r;
}

// Sets this invocation's brick (from the work list) and row; false for the
// workgroups beyond the dispatch's works.
bool locateRow()
{
  const int item = int(gl_WorkGroupID.x + gl_WorkGroupID.y * BAND_MAX_WORKGROUPS_X);
  if (item >= p.works) return false;
  slot = texelFetch(work, p.workOffset + item).x;
  const int lane = int(gl_LocalInvocationID.x);
  y = lane & 7;
  z = lane >> 3;
  origin = texelFetch(origins, slot).xyz;
  return true;
}
