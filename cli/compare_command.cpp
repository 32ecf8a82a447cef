#include <algorithm>
#include <cstdio>
#include <iostream>

#include "lbmshape/analysis/joined_seams.hpp"
#include "lbmshape/analysis/mesh_topology.hpp"
#include "lbmshape/analysis/surface_comparison.hpp"
#include "lbmshape/core/error.hpp"
#include "lbmshape/core/host_memory.hpp"
#include "lbmshape/core/memory_sizes.hpp"
#include "lbmshape/core/parameter_bounds.hpp"
#include "lbmshape/mesh/mesh_reader.hpp"
#include "mesh_commands.hpp"

namespace lbmshape::cli {
namespace {

struct CompareArguments {
  std::string a, b;
  size_t samples = 100000;
  uint64_t seed = 1;
};

nlohmann::json topologyJson(const std::string& path, const JoinedSeams& seen)
{
  const MeshTopology& t = seen.topology;
  return {{"path", path},
          {"joined_vertices", seen.joinedVertices},
          {"vertices", t.vertices},
          {"triangles", t.triangles},
          {"components", t.components},
          {"area", t.area},
          {"volume", t.signedVolume},
          {"genus", t.genus ? nlohmann::json(*t.genus) : nlohmann::json(nullptr)},
          {"closed_manifold", t.closedManifold},
          {"boundary_edges", t.boundaryEdges},
          {"non_manifold_edges", t.nonManifoldEdges},
          {"non_manifold_vertices", t.nonManifoldVertices},
          {"consistently_oriented", t.consistentlyOriented}};
}

nlohmann::json directedJson(const DirectedDistance& d)
{
  return {{"samples", d.samples},
          {"max", d.max},
          {"mean", d.mean},
          {"rms", d.rms},
          {"mean_normal_angle_deg", d.meanNormalAngle}};
}

void printTopology(const char* label, const std::string& path, const JoinedSeams& seen)
{
  const MeshTopology& t = seen.topology;
  std::printf("%s %s\n  %zu vertices, %zu triangles, %zu component(s), area %.6g, volume %.6g\n", label, path.c_str(),
              t.vertices, t.triangles, t.components, t.area, t.signedVolume);
  std::printf("  genus %s, %zu boundary edges, %zu non-manifold edges, %zu non-manifold vertices%s\n",
              t.genus ? std::to_string(*t.genus).c_str() : "- (not a closed manifold)", t.boundaryEdges,
              t.nonManifoldEdges, t.nonManifoldVertices, t.consistentlyOriented ? "" : ", inconsistent orientation");
  if (seen.joinedVertices > 0)
    std::printf("  (%zu vertices at the positions of others joined to them, as denoise joins them)\n",
                seen.joinedVertices);
}

// Refused before sampling where the samples of one direction would not fit
// the host's memory (10 million samples under a 300 MB limit ran out of
// memory with no advice), naming the --samples that would.
void checkSamplesFit(const TriangleMesh& a, const TriangleMesh& b, const ComparisonOptions& options)
{
  const size_t samples =
      std::max(randomSamplesOf(a, options) + a.vertexCount(), randomSamplesOf(b, options) + b.vertexCount());
  const double needed = double(samples) * bytesPerComparisonSample, allowed = double(hostMemoryBytes());
  if (needed <= allowed) return;
  // The samples the meshes' own size asks for (10 a triangle, and the
  // vertices) are taken whatever --samples says.
  ComparisonOptions fewest = options;
  fewest.minSamples = 0;
  const size_t inherent =
      std::max(randomSamplesOf(a, fewest) + a.vertexCount(), randomSamplesOf(b, fewest) + b.vertexCount());
  const auto fitting = size_t(0.9 * allowed / bytesPerComparisonSample);
  const std::string advice =
      fitting > inherent
          ? "--samples " + std::to_string(fitting - std::max(a.vertexCount(), b.vertexCount())) + " would fit"
          : "the meshes' own samples (10 a triangle) do not fit whatever --samples says";
  throw DeviceError("comparing with " + std::to_string(samples) + " samples a surface needs about " +
                    mebibytes(uint64_t(needed)) + " but this machine allows " + mebibytes(uint64_t(allowed)) + "; " +
                    advice);
}

void runCompare(const CommonOptions& common, const CompareArguments& args)
{
  if (args.samples < 1 || args.samples > parameter_bounds::maxSamples)
    throw UsageError("--samples must be from 1 to " + std::to_string(parameter_bounds::maxSamples));
  // Flat meshes too: distances and topology need no inside.
  const TriangleMesh a = readMesh(args.a, EmptyMesh::Refused, FlatMesh::Allowed),
                     b = readMesh(args.b, EmptyMesh::Refused, FlatMesh::Allowed);
  // Topology as denoise reads the meshes (analysis/joined_seams.hpp);
  // distances of the meshes as they are (a seam changes none).
  const JoinedSeams ta = joinSeams(a), tb = joinSeams(b);
  ComparisonOptions options;
  options.minSamples = args.samples;
  options.seed = args.seed;
  options.stopsOnRequest = true;
  checkSamplesFit(a, b, options);
  const SurfaceComparison c = compareSurfaces(a, b, options);
  common.report({{"command", "compare"},
                 {"a", topologyJson(args.a, ta)},
                 {"b", topologyJson(args.b, tb)},
                 {"hausdorff", c.hausdorff},
                 {"mean", c.mean},
                 {"rms", c.rms},
                 {"mean_normal_angle_deg", c.meanNormalAngle},
                 {"a_to_b", directedJson(c.aToB)},
                 {"b_to_a", directedJson(c.bToA)}});
  if (common.json) return;
  printTopology("A", args.a, ta);
  printTopology("B", args.b, tb);
  std::printf("distance (in the meshes' units): Hausdorff %.6g (A->B %.6g, B->A %.6g), mean %.6g, RMS %.6g\n",
              c.hausdorff, c.aToB.max, c.bToA.max, c.mean, c.rms);
  std::printf("mean normal angle error: %.3f degrees\n", c.meanNormalAngle);
}

}  // namespace

void addCompareCommand(CLI::App& app, const CommonOptions& common)
{
  auto args = std::make_shared<CompareArguments>();
  auto* cmd =
      app.add_subcommand("compare", "Distances between two meshes (Hausdorff, mean, RMS, normals) and their topology");
  cmd->add_option("a", args->a, "First mesh")->required();
  cmd->add_option("b", args->b, "Second mesh")->required();
  cmd->add_option("--samples", args->samples, "Random surface samples per mesh, at least")->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the samples")->capture_default_str();
  cmd->callback([&common, args] { runCompare(common, *args); });
}

}  // namespace lbmshape::cli
