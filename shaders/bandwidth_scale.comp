#version 450
// STREAM "scale" on the device, b = s a over vec4s: every byte read once and
// written once, as a lattice step moves its moments, with none of the step's
// arithmetic. `bench` holds the lattice against this bandwidth on a GPU,
// where vkCmdCopyBuffer runs on copy engines at a fraction of it (775 GB/s
// on an H100 that moves 3 TB/s). A grid-stride loop: any number of
// workgroups covers any length.
layout(local_size_x = 256) in;

layout(push_constant) uniform Parameters {
  uint count;  // vec4s
  float scale;
} p;

layout(set = 0, binding = 0, std430) readonly buffer From { vec4 a[]; };
layout(set = 0, binding = 1, std430) writeonly buffer To { vec4 b[]; };

void main()
{
  const uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  for (uint i = gl_GlobalInvocationID.x; i < p.count; i += stride) b[i] = p.scale * a[i];
}
