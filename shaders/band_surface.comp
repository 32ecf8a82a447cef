#version 450
#extension GL_GOOGLE_include_directive : require
// Marching cubes' first half on the device: the cut edges and cut cubes of
// the narrow band's field (band_surface_interface.h has the records), so
// that a morph's frame reads back its surface's pieces, not its field; the
// host makes the triangles from them (surface/surface_pieces.hpp, whose
// listSurfacePieces() is this pass on the CPU). The same pass takes the
// largest |X - X_target| near the target, the morph's convergence check.
// A workgroup is one brick: an invocation a row of its eight cubes, and for
// the edges a row of its 9 x 9 rows of samples (the brick and the first
// layer of the bricks after it) and, where there are more rows than
// invocations, a second one; and a share of the probes.
#include "band_interface.h"
#include "band_surface_interface.h"

layout(local_size_x = BAND_WORKGROUP_SIZE) in;
layout(push_constant) uniform Parameters { SURFACE_PARAMETERS(SURFACE_DECLARE_FIELD) } p;

layout(set = 0, binding = SURFACE_BINDING_FIELD) uniform samplerBuffer field;
layout(set = 0, binding = SURFACE_BINDING_NEIGHBOURS) uniform isamplerBuffer neighbours;
layout(set = 0, binding = SURFACE_BINDING_ORIGINS) uniform isamplerBuffer origins;
layout(set = 0, binding = SURFACE_BINDING_FAR_SIDES) uniform usamplerBuffer farSides;
layout(set = 0, binding = SURFACE_BINDING_BASE) uniform samplerBuffer base;
layout(set = 0, binding = SURFACE_BINDING_COUNTERS, std430) buffer Counters { uint counters[]; };
layout(set = 0, binding = SURFACE_BINDING_CROSSINGS, std430) writeonly buffer Crossings { uvec4 crossings[]; };
layout(set = 0, binding = SURFACE_BINDING_CUBES, std430) writeonly buffer Cubes { uvec4 cubes[]; };
layout(set = 0, binding = SURFACE_BINDING_PROBES) uniform isamplerBuffer probes;
layout(set = 0, binding = SURFACE_BINDING_PROBE_VALUES, std430) writeonly buffer ProbeValues { float probeValues[]; };

const float EDGE_MARGIN = 1e-3;  // edge_vertex::margin
const float LARGEST_FLOAT = 3.402823466e38;

int slot;
ivec3 origin, grid;
uint farBits;
shared int around[27];  // the slots of the bricks at (dx + 1) + 3 (dy + 1) + 9 (dz + 1), -1 for none

// X at brick-local cell l (each coordinate -1 .. 9): from the brick there,
// or the far value on its side where it is not stored (or beyond the grid,
// where no cube reads).
float fetchSample(ivec3 l)
{
  const ivec3 d = l >> 3;  // -1, 0 or 1
  const int k = (d.x + 1) + 3 * (d.y + 1) + 9 * (d.z + 1);
  const int there = around[k];
  if (there >= 0) {
    const ivec3 c = l & 7;
    return texelFetch(field, there * 512 + c.x + 8 * (c.y + 8 * c.z)).x;
  }
  return ((farBits >> k) & 1u) != 0u ? p.farValue : -p.farValue;
}

// The brick's samples and those around it (-1 .. 9 each way), fetched once
// each into shared memory: the cubes and edges read each sample up to a
// dozen times.
const int BLOCK = 11;
shared float block[BLOCK * BLOCK * BLOCK];
shared uint sidesSeen;  // bit 0: a sample of the brick's cubes above the isovalue, bit 1: one not
// Per row (y + 9 z) of the samples of the brick's cubes (0 .. 8 each way):
// bit x set when sample (x, y, z) is above the isovalue. A cube's case and
// a cut edge are then a few bit operations.
shared uint aboveRows[81];

float sampleAt(ivec3 l) { return block[(l.x + 1) + BLOCK * ((l.y + 1) + BLOCK * (l.z + 1))]; }

// edge_vertex::gradient: central differences, one-sided at the grid's faces.
vec3 gradientAt(ivec3 l)
{
  const ivec3 g = origin + l;
  vec3 r;
  for (int a = 0; a < 3; ++a) {
    const int lo = max(g[a] - 1, 0), hi = min(g[a] + 1, grid[a] - 1);
    if (hi == lo) {
      r[a] = 0.0;
      continue;
    }
    ivec3 below = l, above = l;
    below[a] = lo - origin[a];
    above[a] = hi - origin[a];
    r[a] = (sampleAt(above) - sampleAt(below)) / float(hi - lo);
  }
  return r;
}

// Whether the cube with brick-local lower corner c is one of the brick's
// that marching cubes triangulates: in the brick, its upper corner in the grid.
bool cubeOfTheBrick(ivec3 c)
{
  return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(8))) && all(lessThan(origin + c + 1, grid));
}

// Whether one of those cubes has the edge from sample l along `axis`.
bool edgeOfTheBrick(ivec3 l, int axis)
{
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  for (int db = -1; db <= 0; ++db)
    for (int dc = -1; dc <= 0; ++dc) {
      ivec3 cube = l;
      cube[b] += db;
      cube[c] += dc;
      if (cubeOfTheBrick(cube)) return true;
    }
  return false;
}

// The grid index of cell g, as (low, high) words.
uvec2 gridIndex(ivec3 g)
{
  uint high, low, carry;
  umulExtended(uint(p.nx), uint(g.y + p.ny * g.z), high, low);
  low = uaddCarry(low, uint(g.x), carry);
  return uvec2(low, high + carry);
}

// 3 * index + axis, as (low, high) words.
uvec2 edgeKey(uvec2 index, int axis)
{
  uint high, low, carry;
  umulExtended(index.x, 3u, high, low);
  low = uaddCarry(low, uint(axis), carry);
  return uvec2(low, index.y * 3u + high + carry);
}

// Lists the cut edge from sample l along `axis` (its other end in the
// block), if one of the brick's cubes has it and its lower end is in the grid.
void listCrossing(ivec3 l, int axis)
{
  if (any(greaterThanEqual(origin + l, grid)) || !edgeOfTheBrick(l, axis)) return;
  ivec3 u = l;
  u[axis] += 1;
  const float here = sampleAt(l), there = sampleAt(u);
  // edge_vertex::crossing and edge_vertex::normal.
  const float t = clamp((here - p.iso) / (here - there), EDGE_MARGIN, 1.0 - EDGE_MARGIN);
  vec3 outward = -((1.0 - t) * gradientAt(l) + t * gradientAt(u));
  const float size = length(outward);
  if (size > 0.0 && size <= LARGEST_FLOAT) {
    outward /= size;
  } else {
    outward = vec3(0.0);
    outward[axis] = here > p.iso ? 1.0 : -1.0;
  }
  const uint k = atomicAdd(counters[SURFACE_COUNTER_CROSSINGS], 1u);
  if (k < uint(p.crossingCapacity)) {
    crossings[2 * k] = uvec4(edgeKey(gridIndex(origin + l), axis), floatBitsToUint(here), floatBitsToUint(there));
    crossings[2 * k + 1] = uvec4(floatBitsToUint(outward), 0u);
  }
}

// The cut edges from the samples of row (y, z) of the block (0 .. 8 each):
// where two neighbouring samples' bits differ.
void listCrossings(int row)
{
  const int y = row % 9, z = row / 9;
  const uint here = aboveRows[row];
  uint cut[3] = uint[3]((here ^ (here >> 1)) & 0xffu, y < 8 ? (here ^ aboveRows[row + 1]) : 0u,
                        z < 8 ? (here ^ aboveRows[row + 9]) : 0u);
  for (int axis = 0; axis < 3; ++axis)
    for (uint bits = cut[axis]; bits != 0u; bits &= bits - 1u) listCrossing(ivec3(findLSB(bits), y, z), axis);
}

// The cut cubes of row (y, z) of the brick: the case of cube x from bits x
// and x + 1 of the four sample rows around it.
void listCubes(int y, int z)
{
  const uint r00 = aboveRows[y + 9 * z], r10 = aboveRows[y + 1 + 9 * z], r01 = aboveRows[y + 9 * (z + 1)],
             r11 = aboveRows[y + 1 + 9 * (z + 1)];
  const uint all = r00 & r10 & r01 & r11, any = r00 | r10 | r01 | r11;
  // Cubes whose eight corners are neither all above nor all not.
  const uint mixed = ~(all & (all >> 1)) & (any | (any >> 1)) & 0xffu;
  for (uint bits = mixed; bits != 0u; bits &= bits - 1u) {
    const int x = findLSB(bits);
    const ivec3 c = ivec3(x, y, z);
    if (!cubeOfTheBrick(c)) continue;
    const uint cubeCase = (r00 >> x & 3u) | (r10 >> x & 3u) << 2 | (r01 >> x & 3u) << 4 | (r11 >> x & 3u) << 6;
    const uint k = atomicAdd(counters[SURFACE_COUNTER_CUBES], 1u);
    if (k < uint(p.cubeCapacity)) cubes[k] = uvec4(gridIndex(origin + c), cubeCase, uint(slot * 512 + x + 8 * (y + 8 * z)));
  }
}

// The row's stored values: how many are not finite, and the largest
// |X - base| where |base| <= nearBand.
void checkValues(int y, int z)
{
  uint notFinite = 0u;
  float error = 0.0;
  for (int x = 0; x < 8; ++x) {
    const int cell = slot * 512 + x + 8 * (y + 8 * z);
    const float value = texelFetch(field, cell).x;
    if (!(abs(value) <= LARGEST_FLOAT)) notFinite += 1u;
    if (p.nearBand >= 0.0) {
      const float target = texelFetch(base, cell >> 2)[cell & 3];
      if (abs(target) <= p.nearBand) error = max(error, abs(value - target));
    }
  }
  if (notFinite > 0u) atomicAdd(counters[SURFACE_COUNTER_NOT_FINITE], notFinite);
  if (error > 0.0) atomicMax(counters[SURFACE_COUNTER_ERROR], floatBitsToUint(error));
}

void main()
{
  slot = int(gl_WorkGroupID.x + gl_WorkGroupID.y * BAND_MAX_WORKGROUPS_X);
  if (slot >= p.slots) return;
  origin = texelFetch(origins, slot).xyz;
  grid = ivec3(p.nx, p.ny, p.nz);
  farBits = texelFetch(farSides, slot).x;
  const int lane = int(gl_LocalInvocationID.x);
  if (lane < 27) around[lane] = texelFetch(neighbours, slot * 9 + lane / 3)[lane % 3];
  if (lane == 0) sidesSeen = 0u;
  barrier();
  // First the samples of the brick's cubes (0 .. 8 each way): a brick whose
  // samples all lie on one side has no surface, and most of a morph's band
  // is such bricks.
  uint sides = 0u;
  for (int i = lane; i < 9 * 9 * 9; i += BAND_WORKGROUP_SIZE) {
    const ivec3 l = ivec3(i % 9, (i / 9) % 9, i / 81);
    const float value = fetchSample(l);
    block[(l.x + 1) + BLOCK * ((l.y + 1) + BLOCK * (l.z + 1))] = value;
    if (all(lessThan(origin + l, grid))) sides |= value > p.iso ? 1u : 2u;
  }
  if (sides != 0u) atomicOr(sidesSeen, sides);
  barrier();
  checkValues(lane & 7, lane >> 3);
  // The probes, spread over all workgroups.
  for (int i = slot * BAND_WORKGROUP_SIZE + lane; i < p.probes; i += p.slots * BAND_WORKGROUP_SIZE)
    probeValues[i] = texelFetch(field, texelFetch(probes, i).x).x;
  if (sidesSeen != 3u) return;  // the same for the whole workgroup
  // Then the layer around them (-1 and 9), which the gradients read, and
  // the rows' bits.
  for (int i = lane; i < BLOCK * BLOCK * BLOCK; i += BAND_WORKGROUP_SIZE) {
    const ivec3 l = ivec3(i % BLOCK, (i / BLOCK) % BLOCK, i / (BLOCK * BLOCK)) - 1;
    if (any(lessThan(l, ivec3(0))) || any(greaterThan(l, ivec3(8)))) block[i] = fetchSample(l);
  }
  for (int row = lane; row < 81; row += BAND_WORKGROUP_SIZE) {
    uint bits = 0u;
    for (int x = 0; x <= 8; ++x)
      if (sampleAt(ivec3(x, row % 9, row / 9)) > p.iso) bits |= 1u << x;
    aboveRows[row] = bits;
  }
  barrier();
  listCubes(lane & 7, lane >> 3);
  listCrossings(lane);
  if (lane + BAND_WORKGROUP_SIZE < 81) listCrossings(lane + BAND_WORKGROUP_SIZE);
}
