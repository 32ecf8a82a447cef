#version 450
// Puts the lattice in equilibrium with a density field D: the next pull must
// deliver f_j(q) = w_j D(q), so f*_j(q) holds w_j D(q + e_j), or w_j D(q) when
// q + e_j is outside and the wall will bounce the value back to q itself.
// Runs once per job; one cell per invocation keeps it simple.
layout(local_size_x_id = 0) in;
layout(constant_id = 1) const int NX = 1;
layout(constant_id = 2) const int NY = 1;
layout(constant_id = 3) const int NZ = 1;
layout(constant_id = 4) const int ROW = 4;
layout(constant_id = 5) const float W_REST = 1.0 / 3.0;
layout(constant_id = 6) const float W_AXIAL = 1.0 / 18.0;
layout(constant_id = 7) const float W_DIAGONAL = 1.0 / 36.0;

layout(set = 0, binding = 0, std430) readonly buffer Density { float cells[]; } density;
layout(set = 0, binding = 1, std430) writeonly buffer Distribution { float cells[]; } outScalar[19];

const ivec3 velocity[19] = ivec3[](
    ivec3(0, 0, 0),
    ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0), ivec3(0, 0, 1), ivec3(0, 0, -1),
    ivec3(1, 1, 0), ivec3(-1, -1, 0), ivec3(1, -1, 0), ivec3(-1, 1, 0),
    ivec3(1, 0, 1), ivec3(-1, 0, -1), ivec3(1, 0, -1), ivec3(-1, 0, 1),
    ivec3(0, 1, 1), ivec3(0, -1, -1), ivec3(0, 1, -1), ivec3(0, -1, 1));

int cellIndex(ivec3 c) { return c.x + ROW * (c.y + NY * c.z); }

float valueFor(int j, ivec3 cell)
{
  ivec3 target = cell + velocity[j];
  bool inside = all(greaterThanEqual(target, ivec3(0))) && all(lessThan(target, ivec3(NX, NY, NZ)));
  float w = j == 0 ? W_REST : (j <= 6 ? W_AXIAL : W_DIAGONAL);
  return w * density.cells[cellIndex(inside ? target : cell)];
}

void main()
{
  ivec3 cell = ivec3(gl_GlobalInvocationID);
  if (cell.x >= ROW) return;
  int own = cellIndex(cell);
  outScalar[0].cells[own] = valueFor(0, cell);
  outScalar[1].cells[own] = valueFor(1, cell);
  outScalar[2].cells[own] = valueFor(2, cell);
  outScalar[3].cells[own] = valueFor(3, cell);
  outScalar[4].cells[own] = valueFor(4, cell);
  outScalar[5].cells[own] = valueFor(5, cell);
  outScalar[6].cells[own] = valueFor(6, cell);
  outScalar[7].cells[own] = valueFor(7, cell);
  outScalar[8].cells[own] = valueFor(8, cell);
  outScalar[9].cells[own] = valueFor(9, cell);
  outScalar[10].cells[own] = valueFor(10, cell);
  outScalar[11].cells[own] = valueFor(11, cell);
  outScalar[12].cells[own] = valueFor(12, cell);
  outScalar[13].cells[own] = valueFor(13, cell);
  outScalar[14].cells[own] = valueFor(14, cell);
  outScalar[15].cells[own] = valueFor(15, cell);
  outScalar[16].cells[own] = valueFor(16, cell);
  outScalar[17].cells[own] = valueFor(17, cell);
  outScalar[18].cells[own] = valueFor(18, cell);
}
