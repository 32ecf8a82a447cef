#include "lbmshape/surface/loop_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lbmshape {
namespace {

constexpr double impossible = -std::numeric_limits<double>::infinity();

// Shape quality 2 sqrt(3) |n| / sum of squared edges (1 for equilateral)
// times the cosine between n and `reference`, the unit vector area of the
// loop (or 1 when the loop has none).
double score(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& reference,
             bool hasReference)
{
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double squares = glm::dot(b - a, b - a) + glm::dot(c - b, c - b) + glm::dot(a - c, a - c);
  if (!(squares > 0.0)) return -1.0;
  const double projected = hasReference ? glm::dot(n, reference) : glm::length(n);
  return 2.0 * std::sqrt(3.0) * projected / squares;
}

bool isBlocked(const uint16_t* blocked, int i, int j) { return (blocked[i] >> j) & 1u; }

}  // namespace

int triangulateLoop(const glm::dvec3* points, int size, const uint16_t* blocked,
                    std::array<glm::u8vec3, maxLoopSize - 2>& triangles)
{
  if (size < 3 || size > maxLoopSize) return 0;
  if (size == 3) {
    triangles[0] = glm::u8vec3(0, 1, 2);
    return 1;
  }
  glm::dvec3 area(0.0);
  for (int i = 0; i < size; ++i) area += glm::cross(points[i] - points[0], points[(i + 1) % size] - points[0]);
  const double areaLength = glm::length(area);
  const bool hasReference = areaLength > 0.0;
  const glm::dvec3 reference = hasReference ? area / areaLength : glm::dvec3(0.0);

  // best[i][j]: the worst triangle's score in the best triangulation of the
  // sub-polygon i, i+1, ..., j (closed by the chord i-j); split[i][j]: the
  // apex over i-j in it.
  double best[maxLoopSize][maxLoopSize];
  int8_t split[maxLoopSize][maxLoopSize];
  for (int i = 0; i + 1 < size; ++i) best[i][i + 1] = std::numeric_limits<double>::infinity();
  for (int gap = 2; gap < size; ++gap)
    for (int i = 0; i + gap < size; ++i) {
      const int j = i + gap;
      best[i][j] = impossible;
      split[i][j] = -1;
      for (int k = i + 1; k < j; ++k) {
        if ((k - i >= 2 && isBlocked(blocked, i, k)) || (j - k >= 2 && isBlocked(blocked, k, j))) continue;
        if (best[i][k] == impossible || best[k][j] == impossible) continue;
        const double value =
            std::min({score(points[i], points[k], points[j], reference, hasReference), best[i][k], best[k][j]});
        if (split[i][j] < 0 || value > best[i][j]) {
          best[i][j] = value;
          split[i][j] = int8_t(k);
        }
      }
    }
  if (split[0][size - 1] < 0) return 0;

  int count = 0;
  int stack[2 * maxLoopSize][2];
  int depth = 0;
  stack[depth][0] = 0;
  stack[depth++][1] = size - 1;
  while (depth > 0) {
    --depth;
    const int i = stack[depth][0], j = stack[depth][1];
    if (j - i < 2) continue;
    const int k = split[i][j];
    triangles[count++] = glm::u8vec3(i, k, j);
    stack[depth][0] = i;
    stack[depth++][1] = k;
    stack[depth][0] = k;
    stack[depth++][1] = j;
  }
  return count;
}

}  // namespace lbmshape
