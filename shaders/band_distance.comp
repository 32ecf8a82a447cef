#version 450
#extension GL_GOOGLE_include_directive : require
// Stage 1 of the band's signed distance on the device (#18): the exact
// distance from every stored cell of a chunk of bricks to the nearest
// triangle, by a walk of the mesh's hierarchy (TriangleBvh::closest, the
// CPU's reference, step for step: nearer child first, everything farther
// than the best so far pruned). One invocation per cell. The sign stays
// on the CPU (winding_sign.hpp), which needs these distances and a
// handful of winding numbers.
//
// Grid coordinates keep floats well conditioned: a cell's position is
// exact, a corner within half a float step of its double (3e-5 voxel at
// 1024 cells), and the face's distance is taken along the normal the host
// computed in double, not from differences of products that cancel on
// thin triangles.
#include "band_distance_interface.h"

layout(local_size_x = BAND_DISTANCE_WORKGROUP_SIZE) in;
layout(push_constant) uniform Parameters { BAND_DISTANCE_PARAMETERS(BAND_DISTANCE_DECLARE_FIELD) } p;

struct Node {
  vec3 lo;
  uint first;
  vec3 hi;
  uint count;
};
layout(set = 0, binding = BAND_DISTANCE_BINDING_NODES, std430) readonly buffer Nodes { Node nodes[]; };
layout(set = 0, binding = BAND_DISTANCE_BINDING_TRIANGLES, std430) readonly buffer Triangles { vec4 triangles[]; };
layout(set = 0, binding = BAND_DISTANCE_BINDING_ORIGINS, std430) readonly buffer Origins { ivec4 origins[]; };
layout(set = 0, binding = BAND_DISTANCE_BINDING_DISTANCES, std430) writeonly buffer Distances { float distances[]; };

float boxDistance2(vec3 q, uint node)
{
  const vec3 gap = max(max(nodes[node].lo - q, q - nodes[node].hi), vec3(0.0));
  return dot(gap, gap);
}

float segmentDistance2(vec3 q, vec3 a, vec3 b)
{
  const vec3 ab = b - a, aq = q - a;
  const float length2 = dot(ab, ab);
  const float t = length2 > 0.0 ? clamp(dot(aq, ab) / length2, 0.0, 1.0) : 0.0;
  const vec3 gap = aq - t * ab;
  return dot(gap, gap);
}

// PreparedTriangle::closestPoint's regions (Ericson 5.1.5), as squared distances.
float triangleDistance2(vec3 q, uint slot)
{
  const vec4 a4 = triangles[4 * slot];
  const vec3 a = a4.xyz, b = triangles[4 * slot + 1].xyz, c = triangles[4 * slot + 2].xyz;
  if (a4.w != 0.0) return min(segmentDistance2(q, a, b), min(segmentDistance2(q, b, c), segmentDistance2(q, c, a)));
  const vec3 ab = b - a, ac = c - a, aq = q - a;
  const float d1 = dot(ab, aq), d2 = dot(ac, aq);
  if (d1 <= 0.0 && d2 <= 0.0) return dot(aq, aq);
  const float abab = dot(ab, ab), abac = dot(ab, ac), acac = dot(ac, ac);
  const float d3 = d1 - abab, d4 = d2 - abac;
  const vec3 bq = q - b;
  if (d3 >= 0.0 && d4 <= d3) return dot(bq, bq);
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const vec3 gap = aq - (d1 / (d1 - d3)) * ab;
    return dot(gap, gap);
  }
  const float d5 = d1 - abac, d6 = d2 - acac;
  const vec3 cq = q - c;
  if (d6 >= 0.0 && d5 <= d6) return dot(cq, cq);
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const vec3 gap = aq - (d2 / (d2 - d6)) * ac;
    return dot(gap, gap);
  }
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const vec3 gap = bq - ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    return dot(gap, gap);
  }
  const float height = dot(aq, triangles[4 * slot + 3].xyz);
  return height * height;
}

void main()
{
  const int local = int(gl_GlobalInvocationID.x) % 512, slot = p.firstSlot + int(gl_GlobalInvocationID.x) / 512;
  if (slot >= p.firstSlot + p.slots) return;
  const ivec3 cell = origins[slot].xyz + ivec3(local & 7, (local >> 3) & 7, local >> 6);
  const uint out_ = gl_GlobalInvocationID.x;
  if (any(greaterThanEqual(cell, ivec3(p.nx, p.ny, p.nz)))) {
    distances[out_] = uintBitsToFloat(0x7f800000u);  // +inf: beyond the grid, never read
    return;
  }
  const vec3 q = vec3(cell);
  // A triangle exactly at the bound must not be lost to rounding.
  float best2 = p.bound2 * (1.0 + 1e-6);
  bool found = false;
  uint stackNode[BAND_DISTANCE_STACK];
  float stackDistance2[BAND_DISTANCE_STACK];
  int top = 0;
  stackNode[0] = 0u, stackDistance2[0] = boxDistance2(q, 0u), top = 1;
  while (top > 0) {
    --top;
    if (stackDistance2[top] > best2) continue;
    const uint node = stackNode[top];
    const uint count = nodes[node].count, first = nodes[node].first;
    if (count > 0u) {
      for (uint s = first; s < first + count; ++s) {
        const float d2 = triangleDistance2(q, s);
        if (d2 < best2 || (!found && d2 <= best2)) best2 = d2, found = true;
      }
      continue;
    }
    const uint left = node + 1u, right = first;
    const float dl = boxDistance2(q, left), dr = boxDistance2(q, right);
    const bool leftNearer = dl <= dr;
    const float nearD2 = leftNearer ? dl : dr, farD2 = leftNearer ? dr : dl;
    if (farD2 <= best2) stackNode[top] = leftNearer ? right : left, stackDistance2[top] = farD2, ++top;
    if (nearD2 <= best2) stackNode[top] = leftNearer ? left : right, stackDistance2[top] = nearD2, ++top;
  }
  distances[out_] = found ? sqrt(best2) : uintBitsToFloat(0x7f800000u);
}
