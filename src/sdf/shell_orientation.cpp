#include "lbmshape/sdf/shell_orientation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "lbmshape/sdf/triangle_bvh.hpp"

namespace lbmshape {
namespace {

// A triangle's use of an edge (a < b), and whether it runs a -> b.
struct EdgeUse {
  uint32_t a, b, triangle;
  bool forward;
};

// The triangles joined to each triangle through an edge that exactly two
// share (`sameWay`: both run it in the same direction, so one of them is
// turned), as compressed rows; and the triangles that touch an edge used
// once or more than twice (not part of a closed piece).
struct Neighbours {
  std::vector<size_t> rowStart;
  std::vector<std::pair<uint32_t, bool>> joined;  // (triangle, sameWay)
  std::vector<bool> touchesAnOpenEdge;
};

Neighbours neighboursOf(const TriangleMesh& mesh)
{
  const size_t n = mesh.triangles.size();
  std::vector<EdgeUse> uses;
  uses.reserve(3 * n);
  for (uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t u = mesh.triangles[t][k], v = mesh.triangles[t][(k + 1) % 3];
      if (u != v) uses.push_back({std::min(u, v), std::max(u, v), t, u < v});
    }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return std::tie(x.a, x.b, x.triangle) < std::tie(y.a, y.b, y.triangle);
  });
  Neighbours result;
  result.touchesAnOpenEdge.assign(n, false);
  std::vector<std::pair<uint32_t, std::pair<uint32_t, bool>>> pairs;  // (triangle, (neighbour, sameWay))
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b) ++j;
    if (j - i == 2) {
      const bool sameWay = uses[i].forward == uses[i + 1].forward;
      pairs.push_back({uses[i].triangle, {uses[i + 1].triangle, sameWay}});
      pairs.push_back({uses[i + 1].triangle, {uses[i].triangle, sameWay}});
    } else {
      for (size_t k = i; k < j; ++k) result.touchesAnOpenEdge[uses[k].triangle] = true;
    }
    i = j;
  }
  std::sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  result.rowStart.assign(n + 1, 0);
  for (const auto& p : pairs) ++result.rowStart[p.first + 1];
  for (size_t t = 0; t < n; ++t) result.rowStart[t + 1] += result.rowStart[t];
  result.joined.reserve(pairs.size());
  for (const auto& p : pairs) result.joined.push_back(p.second);
  return result;
}

void turnOver(glm::uvec3& triangle) { std::swap(triangle[1], triangle[2]); }

// The volume a closed piece encloses, taken about its first corner (any
// point gives the same for a closed piece; a near one loses fewer digits).
double signedVolume(const TriangleMesh& mesh, const std::vector<uint32_t>& piece)
{
  const glm::dvec3 o = mesh.positions[mesh.triangles[piece.front()][0]];
  double sixTimes = 0.0;
  for (const uint32_t t : piece) {
    const glm::uvec3& c = mesh.triangles[t];
    sixTimes += glm::dot(mesh.positions[c[0]] - o, glm::cross(mesh.positions[c[1]] - o, mesh.positions[c[2]] - o));
  }
  return sixTimes / 6.0;
}

// A point just off triangle t on the side its normal points away from:
// outside the closed piece t belongs to if that piece faces in, where the
// piece's own winding number is 0 and the mesh's is that of the others.
glm::dvec3 justBehind(const TriangleMesh& mesh, uint32_t t)
{
  const glm::uvec3& c = mesh.triangles[t];
  const glm::dvec3 a = mesh.positions[c[0]], b = mesh.positions[c[1]], d = mesh.positions[c[2]];
  const glm::dvec3 normal = glm::normalize(glm::cross(b - a, d - a));
  const double size = std::max({glm::distance(a, b), glm::distance(b, d), glm::distance(d, a)});
  return (a + b + d) / 3.0 - 1e-3 * size * normal;
}

// A piece alone, its vertices renumbered: for its own winding number.
TriangleMesh pieceAlone(const TriangleMesh& mesh, const std::vector<uint32_t>& piece)
{
  TriangleMesh alone;
  std::unordered_map<uint32_t, uint32_t> renumbered;  // a piece's own size, however many pieces
  for (const uint32_t t : piece) {
    glm::uvec3 corners;
    for (int k = 0; k < 3; ++k) {
      const auto [at, added] = renumbered.try_emplace(mesh.triangles[t][k], uint32_t(alone.positions.size()));
      if (added) alone.positions.push_back(mesh.positions[mesh.triangles[t][k]]);
      corners[k] = at->second;
    }
    alone.triangles.push_back(corners);
  }
  return alone;
}

// The centroid of a piece's corners.
glm::dvec3 centroid(const TriangleMesh& mesh, const std::vector<uint32_t>& piece)
{
  glm::dvec3 sum(0.0);
  for (const uint32_t t : piece)
    for (int k = 0; k < 3; ++k) sum += mesh.positions[mesh.triangles[t][k]];
  return sum / double(3 * piece.size());
}

// Points just behind a closed piece's outermost triangles along each axis
// and ten spread over its list: where it is judged to lie inside others.
// One point, its first triangle's, let the file's order decide whether a
// shell pushed partly through another (a pin through a ball) was a cavity.
std::vector<glm::dvec3> probePoints(const TriangleMesh& mesh, const std::vector<uint32_t>& piece)
{
  std::vector<glm::dvec3> points;
  for (int axis = 0; axis < 3; ++axis) {
    const auto along = [&](uint32_t t) { return mesh.positions[mesh.triangles[t][0]][axis]; };
    const auto [lowest, highest] =
        std::minmax_element(piece.begin(), piece.end(), [&](uint32_t a, uint32_t b) { return along(a) < along(b); });
    points.push_back(justBehind(mesh, *lowest));
    points.push_back(justBehind(mesh, *highest));
  }
  constexpr size_t spread = 10;
  for (size_t k = 0; k < spread; ++k) points.push_back(justBehind(mesh, piece[k * piece.size() / spread]));
  return points;
}

// Whether all the points lie inside what `tree` holds (|w| >= 1/2).
bool allInside(const std::vector<glm::dvec3>& points, const TriangleBvh& tree)
{
  return std::all_of(points.begin(), points.end(),
                     [&](const glm::dvec3& p) { return std::abs(tree.windingNumber(p)) >= 0.5; });
}

// A mirrored hollow part: its outer shell faces in, and is turned, but the
// shell of its cavity, mirrored too, faces out, and the part came out solid.
// So every closed piece inside a shell just turned is made to face as its
// depth among them says: in (a cavity) inside an odd number of them, out
// inside an even number (a ball in the cavity). Returns how many turned.
// A piece holds another when all of the other's probe points lie inside it
// (its own winding number): pieces that overlap without nesting (a pin
// through a ball) hold nothing.
size_t faceTheNestedByDepth(TriangleMesh& mesh, const std::vector<std::vector<uint32_t>>& pieces,
                            const std::vector<uint32_t>& closedPieces, const std::vector<uint32_t>& turnedOuter)
{
  constexpr size_t mostNested = 64;  // pairs of pieces are tested: a bound on the work
  std::vector<uint32_t> involved = turnedOuter;
  std::vector<TriangleBvh> trees;
  for (const uint32_t id : turnedOuter) trees.emplace_back(pieceAlone(mesh, pieces[id]));
  std::vector<uint32_t> nested;
  for (const uint32_t id : closedPieces) {
    if (std::find(turnedOuter.begin(), turnedOuter.end(), id) != turnedOuter.end()) continue;
    const std::vector<glm::dvec3> points = probePoints(mesh, pieces[id]);
    if (std::any_of(trees.begin(), trees.end(), [&](const TriangleBvh& outer) { return allInside(points, outer); }))
      nested.push_back(id);
    if (nested.size() > mostNested) return 0;
  }
  for (const uint32_t id : nested) trees.emplace_back(pieceAlone(mesh, pieces[id]));
  involved.insert(involved.end(), nested.begin(), nested.end());
  size_t turned = 0;
  for (const uint32_t id : nested) {
    const std::vector<glm::dvec3> points = probePoints(mesh, pieces[id]);
    int depth = 0;
    for (size_t k = 0; k < involved.size(); ++k)
      if (involved[k] != id && allInside(points, trees[k])) ++depth;
    const bool shouldFaceIn = depth % 2 == 1;
    if ((signedVolume(mesh, pieces[id]) < 0.0) != shouldFaceIn) {
      for (const uint32_t t : pieces[id]) turnOver(mesh.triangles[t]);
      ++turned;
    }
  }
  return turned;
}

// Open pieces inside out (a mirrored scan, whole or in pieces) have a
// winding number of about -1 where they are solid, and enclosed nothing.
// A piece is turned when, at its corners' centroid, its own winding number
// and the whole mesh's are both -3/4 or less: a scan with holes has about
// -1 there, while a sheet curved over its centroid (a hump) may pass -1/2
// (-0.56 under the sine hump of the tests) and a shape whose centroid lies
// outside it (a ring) about 0, and are left; the whole mesh's keeps the
// inner wall of a holed hollow part (-1 alone, 0 with the outer wall that
// holds it) as it faces. Where no piece alone is so, the open pieces
// together are judged the same way at their common centroid (a scan in
// patches, every patch reversed). Returns how many were turned.
size_t turnOpenPiecesInsideOut(TriangleMesh& mesh, const std::vector<std::vector<uint32_t>>& pieces,
                               const std::vector<uint32_t>& openPieces)
{
  if (openPieces.empty()) return 0;
  constexpr double deepInside = -0.75;
  std::optional<TriangleBvh> whole;
  if (pieces.size() > 1) whole.emplace(mesh);
  const auto insideOutAt = [&](const std::vector<uint32_t>& triangles) {
    const glm::dvec3 c = centroid(mesh, triangles);
    return TriangleBvh(pieceAlone(mesh, triangles)).windingNumber(c) <= deepInside &&
           (!whole || whole->windingNumber(c) <= deepInside);
  };
  std::vector<uint32_t> turned;
  for (const uint32_t id : openPieces)
    if (pieces[id].size() >= 4 && insideOutAt(pieces[id])) turned.push_back(id);
  if (turned.empty() && openPieces.size() > 1) {
    std::vector<uint32_t> together;
    for (const uint32_t id : openPieces) together.insert(together.end(), pieces[id].begin(), pieces[id].end());
    if (insideOutAt(together)) turned = openPieces;
  }
  for (const uint32_t id : turned)
    for (const uint32_t t : pieces[id]) turnOver(mesh.triangles[t]);
  return turned.size();
}

}  // namespace

Reorientation orientShells(TriangleMesh& mesh)
{
  const size_t n = mesh.triangles.size();
  const Neighbours neighbours = neighboursOf(mesh);
  constexpr uint32_t unvisited = UINT32_MAX;
  std::vector<uint32_t> pieceOf(n, unvisited);
  std::vector<bool> turn(n, false);
  std::vector<std::vector<uint32_t>> pieces;
  Reorientation done;
  size_t disagreements = 0;  // each counted from both sides
  for (uint32_t seed = 0; seed < n; ++seed) {
    if (pieceOf[seed] != unvisited) continue;
    const uint32_t id = uint32_t(pieces.size());
    std::vector<uint32_t> piece{seed};
    pieceOf[seed] = id;
    for (size_t next = 0; next < piece.size(); ++next) {
      const uint32_t t = piece[next];
      for (size_t k = neighbours.rowStart[t]; k < neighbours.rowStart[t + 1]; ++k) {
        const auto [u, sameWay] = neighbours.joined[k];
        const bool wanted = turn[t] != sameWay;
        if (pieceOf[u] == unvisited) {
          pieceOf[u] = id;
          turn[u] = wanted;
          piece.push_back(u);
        } else if (turn[u] != wanted) {
          ++disagreements;
        }
      }
    }
    // The orientation most of the piece's triangles had wins.
    const size_t turned = size_t(std::count_if(piece.begin(), piece.end(), [&](uint32_t t) { return turn[t]; }));
    const bool flipAll = 2 * turned > piece.size();
    for (const uint32_t t : piece) {
      if (turn[t] != flipAll) {
        turnOver(mesh.triangles[t]);
        ++done.trianglesTurned;
      }
    }
    pieces.push_back(std::move(piece));
  }
  done.unorientableEdges = disagreements / 2;

  // Closed pieces facing in, inside no other piece: inside out. Each is
  // judged on the mesh as it is now, then the ones found are turned.
  std::vector<uint32_t> facingIn, closedPieces, openPieces;
  for (uint32_t id = 0; id < pieces.size(); ++id) {
    const std::vector<uint32_t>& piece = pieces[id];
    const bool closed =
        std::none_of(piece.begin(), piece.end(), [&](uint32_t t) { return neighbours.touchesAnOpenEdge[t]; });
    (closed ? closedPieces : openPieces).push_back(id);
    if (closed && signedVolume(mesh, piece) < 0.0) facingIn.push_back(id);
  }
  if (!facingIn.empty()) {
    std::optional<TriangleBvh> tree;  // the winding number of all pieces at once, for any number of them
    if (pieces.size() > 1) tree.emplace(mesh);
    std::vector<uint32_t> insideOut;
    for (const uint32_t id : facingIn)
      if (!tree || !allInside(probePoints(mesh, pieces[id]), *tree)) insideOut.push_back(id);
    for (const uint32_t id : insideOut)
      for (const uint32_t t : pieces[id]) turnOver(mesh.triangles[t]);
    done.shellsTurned = insideOut.size();
    if (!insideOut.empty() && closedPieces.size() > insideOut.size())
      done.nestedShellsTurned = faceTheNestedByDepth(mesh, pieces, closedPieces, insideOut);
  }
  done.openPiecesTurned = turnOpenPiecesInsideOut(mesh, pieces, openPieces);
  return done;
}

}  // namespace lbmshape
