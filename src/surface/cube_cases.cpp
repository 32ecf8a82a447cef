#include "lbmshape/surface/cube_cases.hpp"

#include <stdexcept>
#include <string>

namespace lbmshape::cube {
namespace {

int cornerAt(int x, int y, int z) { return x | (y << 1) | (z << 2); }

std::array<Edge, 12> makeEdges()
{
  std::array<Edge, 12> result{};
  for (int axis = 0; axis < 3; ++axis) {
    // k holds the other two coordinates, the lower-numbered axis in bit 0.
    const int first = axis == 0 ? 1 : 0, second = axis == 2 ? 1 : 2;
    for (int k = 0; k < 4; ++k) {
      int offset[3] = {0, 0, 0};
      offset[first] = k & 1;
      offset[second] = k >> 1;
      const int lower = cornerAt(offset[0], offset[1], offset[2]);
      result[axis * 4 + k] = Edge{uint8_t(axis), uint8_t(lower), uint8_t(lower | (1 << axis))};
    }
  }
  return result;
}

std::array<Face, 6> makeFaces()
{
  std::array<Face, 6> result{};
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      // (u, v, axis) is right-handed, so (0,0) (1,0) (1,1) (0,1) in (u, v) runs
      // counter-clockwise around +axis; the low face looks along -axis.
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const int square[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      Face face{uint8_t(axis), uint8_t(side), {}};
      for (int i = 0; i < 4; ++i) {
        const int* uv = square[side == 1 ? i : (4 - i) % 4];
        int offset[3];
        offset[axis] = side;
        offset[u] = uv[0];
        offset[v] = uv[1];
        face.corners[i] = uint8_t(cornerAt(offset[0], offset[1], offset[2]));
      }
      result[axis * 2 + side] = face;
    }
  return result;
}

int edgeBetween(int a, int b)
{
  const auto& all = edges();
  for (int e = 0; e < 12; ++e)
    if ((all[e].lower == a && all[e].upper == b) || (all[e].lower == b && all[e].upper == a)) return e;
  throw std::logic_error("cube corners " + std::to_string(a) + " and " + std::to_string(b) + " share no edge");
}

bool shareFace(int e0, int e1)
{
  for (const Face& face : faces()) {
    int found = 0;
    for (int i = 0; i < 4; ++i) {
      const int e = edgeBetween(face.corners[i], face.corners[(i + 1) % 4]);
      found += (e == e0) + (e == e1);
    }
    if (found == 2) return true;
  }
  return false;
}

CubeCase makeCase(int index)
{
  auto inside = [&](int corner) { return (index >> corner) & 1; };
  // next[e]: the cut edge that follows e along the surface's boundary loop.
  std::array<int, 12> next;
  next.fill(-1);
  for (const Face& face : faces()) {
    // Walking the face counter-clockwise (seen from outside the cube), an
    // inside run starts at an entering edge (outside -> inside) and ends at a
    // leaving edge. The inside region's boundary runs counter-clockwise, so
    // the outward surface's boundary runs the opposite way along the shared
    // segment: from the entering edge to the leaving edge. Pairing each
    // entering edge with the end of its own run keeps diagonal inside corners
    // apart.
    for (int i = 0; i < 4; ++i) {
      const int a = face.corners[i], b = face.corners[(i + 1) % 4];
      if (inside(a) || !inside(b)) continue;
      for (int k = 1; k < 4; ++k) {
        const int c = face.corners[(i + k) % 4], d = face.corners[(i + k + 1) % 4];
        if (inside(c) && !inside(d)) {
          next[edgeBetween(a, b)] = edgeBetween(c, d);
          break;
        }
      }
    }
  }
  CubeCase result;
  std::array<bool, 12> visited{};
  std::array<uint8_t, 12> loopOf{};
  for (int start = 0; start < 12; ++start) {
    if (next[start] < 0 || visited[start]) continue;
    if (result.loopCount == CubeCase::maxLoops) throw std::logic_error("cube case with more than four loops");
    int size = 0;
    for (int e = start; !visited[e]; e = next[e]) {
      if (next[e] < 0) throw std::logic_error("open loop in cube case " + std::to_string(index));
      visited[e] = true;
      loopOf[result.edgeCount] = result.loopCount;
      result.edges[result.edgeCount++] = uint8_t(e);
      ++size;
    }
    result.loopSize[result.loopCount++] = uint8_t(size);
  }
  // Chords between two edges of one face are blocked unless the face has a
  // segment between them, which makes them neighbours in their loop anyway.
  for (int i = 0; i < result.edgeCount; ++i)
    for (int j = 0; j < result.edgeCount; ++j)
      if (i != j && loopOf[i] == loopOf[j] && next[result.edges[i]] != result.edges[j] &&
          next[result.edges[j]] != result.edges[i] && shareFace(result.edges[i], result.edges[j]))
        result.blockedChords[i] |= uint16_t(1u << j);
  return result;
}

}  // namespace

const std::array<Edge, 12>& edges()
{
  static const std::array<Edge, 12> table = makeEdges();
  return table;
}

const std::array<Face, 6>& faces()
{
  static const std::array<Face, 6> table = makeFaces();
  return table;
}

const std::array<CubeCase, 256>& cubeCases()
{
  static const std::array<CubeCase, 256> table = [] {
    std::array<CubeCase, 256> cases;
    for (int i = 0; i < 256; ++i) cases[i] = makeCase(i);
    return cases;
  }();
  return table;
}

}  // namespace lbmshape::cube
