#include "lbmshape/analysis/normal_noise.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace lbmshape {
namespace {

constexpr uint32_t notNeeded = std::numeric_limits<uint32_t>::max();

// The vertices the estimate reads (`sampled`) and their neighbours, each
// with its ring of neighbours (each edge once), whether it lies on an edge
// that is not in exactly two triangles (a rim or a non-manifold seam, where
// a ring is not a ring), and its area-weighted normal. Only these are
// built, so the cost follows the sample, not the mesh.
struct Rings {
  std::vector<uint32_t> slot;    // per mesh vertex: its place here, or notNeeded
  std::vector<uint32_t> vertex;  // per place: the mesh vertex
  std::vector<size_t> first;     // per place, into `neighbours`; one more than the places
  std::vector<uint32_t> neighbours;
  std::vector<bool> onRim;
  std::vector<glm::dvec3> normal;

  size_t valence(uint32_t place) const { return first[place + 1] - first[place]; }
};

bool hasRepeatedCorner(const glm::uvec3& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; }

Rings ringsAround(const TriangleMesh& mesh, const std::vector<uint32_t>& sampled)
{
  Rings rings;
  const size_t vertices = mesh.vertexCount();
  std::vector<bool> isSampled(vertices, false);
  for (uint32_t v : sampled) isSampled[v] = true;
  rings.slot.assign(vertices, notNeeded);
  const auto need = [&](uint32_t v) {
    if (rings.slot[v] != notNeeded) return;
    rings.slot[v] = uint32_t(rings.vertex.size());
    rings.vertex.push_back(v);
  };
  // A triangle with a repeated corner has no area and lists one edge
  // twice: it would make a rim edge look interior.
  for (const glm::uvec3& t : mesh.triangles)
    if (!hasRepeatedCorner(t) && (isSampled[t[0]] || isSampled[t[1]] || isSampled[t[2]]))
      for (int i = 0; i < 3; ++i) need(t[i]);
  const size_t places = rings.vertex.size();
  // Each corner lists its triangle's other two corners; an edge in two
  // triangles is listed twice at each end.
  std::vector<size_t> first(places + 1, 0);
  for (const glm::uvec3& t : mesh.triangles)
    if (!hasRepeatedCorner(t))
      for (int i = 0; i < 3; ++i)
        if (rings.slot[t[i]] != notNeeded) first[rings.slot[t[i]] + 1] += 2;
  for (size_t p = 0; p < places; ++p) first[p + 1] += first[p];
  std::vector<uint32_t> listed(first.back());
  std::vector<size_t> filled(first.begin(), first.end() - 1);
  rings.normal.assign(places, glm::dvec3(0.0));
  for (const glm::uvec3& t : mesh.triangles) {
    if (hasRepeatedCorner(t)) continue;
    const glm::dvec3 area =
        glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
    for (int i = 0; i < 3; ++i) {
      const uint32_t p = rings.slot[t[i]];
      if (p == notNeeded) continue;
      listed[filled[p]++] = t[(i + 1) % 3];
      listed[filled[p]++] = t[(i + 2) % 3];
      rings.normal[p] += area;
    }
  }
  rings.onRim.assign(places, false);
  rings.first.assign(places + 1, 0);
  for (size_t p = 0; p < places; ++p) {
    const auto begin = listed.begin() + std::ptrdiff_t(first[p]), end = listed.begin() + std::ptrdiff_t(first[p + 1]);
    std::sort(begin, end);
    for (auto at = begin; at != end;) {
      const auto next = std::upper_bound(at, end, *at);
      if (next - at != 2) rings.onRim[p] = true;
      rings.neighbours.push_back(*at);
      at = next;
    }
    rings.first[p + 1] = rings.neighbours.size();
  }
  return rings;
}

constexpr double notKnown = std::numeric_limits<double>::quiet_NaN();

// Each place's offset from its neighbours' centroid along its normal; NaN
// on a rim, with fewer than three neighbours, or with no normal.
std::vector<double> offsetsAlongNormals(const TriangleMesh& mesh, const Rings& rings)
{
  std::vector<double> offsets(rings.vertex.size(), notKnown);
  for (uint32_t p = 0; p < rings.vertex.size(); ++p) {
    const size_t k = rings.valence(p);
    const double length = glm::length(rings.normal[p]);
    if (rings.onRim[p] || k < 3 || !(length > 0.0)) continue;
    glm::dvec3 centroid(0.0);
    for (size_t i = rings.first[p]; i < rings.first[p + 1]; ++i) centroid += mesh.positions[rings.neighbours[i]];
    offsets[p] = glm::dot(rings.normal[p] / length, mesh.positions[rings.vertex[p]] - centroid / double(k));
  }
  return offsets;
}

// The root sum of squares of the weights with which the second difference
// at place p sums the vertices' own displacements along the normals: 1 at
// its vertex, -1/k_v twice at each neighbour u (its offset and the mean of
// theirs), and 1/(k_v k_u) at each of u's neighbours.
double weightNorm(uint32_t p, const Rings& rings, std::vector<std::pair<uint32_t, double>>& weights)
{
  weights.clear();
  const double kv = double(rings.valence(p));
  weights.emplace_back(rings.vertex[p], 1.0);
  for (size_t i = rings.first[p]; i < rings.first[p + 1]; ++i) {
    const uint32_t u = rings.slot[rings.neighbours[i]];
    weights.emplace_back(rings.vertex[u], -2.0 / kv);
    const double share = 1.0 / (kv * double(rings.valence(u)));
    for (size_t j = rings.first[u]; j < rings.first[u + 1]; ++j) weights.emplace_back(rings.neighbours[j], share);
  }
  std::sort(weights.begin(), weights.end());
  double sumOfSquares = 0.0;
  for (size_t i = 0; i < weights.size();) {
    double w = 0.0;
    const uint32_t at = weights[i].first;
    for (; i < weights.size() && weights[i].first == at; ++i) w += weights[i].second;
    sumOfSquares += w * w;
  }
  return std::sqrt(sumOfSquares);
}

double median(std::vector<double>& values)
{
  const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// At most `most` vertices, evenly spread over the numbering.
std::vector<uint32_t> sampleOf(size_t vertices, size_t most)
{
  const size_t stride = most >= vertices ? 1 : vertices / most + (vertices % most != 0);
  std::vector<uint32_t> sampled;
  for (size_t v = 0; v < vertices; v += stride) sampled.push_back(uint32_t(v));
  return sampled;
}

}  // namespace

std::optional<double> normalNoiseAmplitude(const TriangleMesh& mesh, size_t mostVertices)
{
  const std::vector<uint32_t> sampled = sampleOf(mesh.vertexCount(), std::max<size_t>(mostVertices, 1));
  const Rings rings = ringsAround(mesh, sampled);
  const std::vector<double> offsets = offsetsAlongNormals(mesh, rings);
  std::vector<double> samples;
  std::vector<std::pair<uint32_t, double>> weights;
  for (uint32_t v : sampled) {
    const uint32_t p = rings.slot[v];
    if (p == notNeeded || std::isnan(offsets[p])) continue;
    double neighbours = 0.0;
    bool closed = true;
    for (size_t i = rings.first[p]; i < rings.first[p + 1] && closed; ++i) {
      const double o = offsets[rings.slot[rings.neighbours[i]]];
      closed = !std::isnan(o);
      neighbours += o;
    }
    if (!closed) continue;
    const double secondDifference = offsets[p] - neighbours / double(rings.valence(p));
    samples.push_back(secondDifference / weightNorm(p, rings, weights));
  }
  if (samples.size() < 32) return std::nullopt;
  const double centre = median(samples);
  for (double& s : samples) s = std::abs(s - centre);
  return 1.4826 * median(samples);
}

}  // namespace lbmshape
