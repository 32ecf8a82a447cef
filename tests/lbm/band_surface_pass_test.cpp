// The device's marching-cubes pass (shaders/band_surface.comp) against its
// CPU reference, listSurfacePieces() of the same field: a morph's frame
// reads back these pieces instead of its field.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/lbm/band_vulkan_solver.hpp"
#include "lbmshape/gpu/device_description.hpp"
#include "lbmshape/gpu/gpu_context.hpp"
#include "lbmshape/pipeline/compute_device.hpp"
#include "support/band_fields.hpp"
#include "support/fields.hpp"
#include "lbmshape/surface/band_marching_cubes.hpp"
#include "lbmshape/surface/surface_pieces.hpp"

namespace lbmshape {
namespace {

using testing::Backend;

class BandSurfacePass : public testing::GpuTest {
protected:
  // A morph on the device: a noisy sphere towards another sphere, the
  // band `reach` voxels around the first (a small reach leaves cubes
  // whose corners lie in bricks not stored).
  struct Morph {
    std::unique_ptr<BandSolver> solver;
    BandField target;
  };
  Morph startMorph(double reach, float noise, Backend backend = Backend::Vulkan)
  {
    const Extent3 extent{37, 29, 45};  // sides that are no multiple of 8; the sphere reaches the faces
    Volume field = testing::sphereDistance(extent, 18.0, 14.5, 22.0, 17.0);
    const Volume bumps = testing::randomField(extent, -noise, noise, 7);
    for (size_t i = 0; i < field.size(); ++i) field.values()[i] += bumps.values()[i];
    auto bricks = testing::bricksNear(field, reach);
    Morph m{testing::makeBandSolver(backend, bricks),
            testing::bandOf(testing::sphereDistance(extent, 20.0, 14.0, 20.0, 12.0), bricks)};
    m.solver->setUniformGamma(0.15);
    m.solver->setSource(BandSource{m.target, 0.1f, 0.1f});
    m.solver->initialize(testing::bandOf(field, bricks), std::min(reach, 6.0));
    return m;
  }
};

// The two lists alike: every key, value and case exactly, the normals to
// float rounding (the reference takes the gradients in double).
void expectSamePieces(const SurfacePieces& got, const SurfacePieces& expected)
{
  ASSERT_EQ(got.crossings.size(), expected.crossings.size());
  ASSERT_EQ(got.cubes.size(), expected.cubes.size());
  EXPECT_EQ(got.extent, expected.extent);
  size_t keys = 0, values = 0, normals = 0, cubes = 0;
  for (size_t k = 0; k < got.crossings.size(); ++k) {
    const SurfaceCrossing &a = got.crossings[k], &b = expected.crossings[k];
    keys += a.key != b.key;
    values += a.lower != b.lower || a.upper != b.upper;
    normals += !(glm::length(a.normal - b.normal) <= 1e-5f);
  }
  for (size_t k = 0; k < got.cubes.size(); ++k)
    cubes += got.cubes[k].index != expected.cubes[k].index || got.cubes[k].cubeCase != expected.cubes[k].cubeCase ||
             got.cubes[k].order != expected.cubes[k].order;
  EXPECT_EQ(keys, 0u) << "crossings at other edges";
  EXPECT_EQ(values, 0u) << "crossings with other values";
  EXPECT_EQ(normals, 0u) << "normals more than 1e-5 apart";
  EXPECT_EQ(cubes, 0u) << "other cubes or cases";
  EXPECT_GT(got.crossings.size(), 100u) << "a surface";
}

TEST_F(BandSurfacePass, ListsWhatTheReferenceListsFromTheSameField)
{
  for (const double reach : {7.0, 1.0}) {
    SCOPED_TRACE("reach " + std::to_string(reach));
    Morph m = startMorph(reach, 0.3f);
    m.solver->step(6);
    // Probes every fifth cell, stored or not.
    SurfaceRequest request{.nearBand = 1.0f};
    const Extent3 e = m.target.extent();
    for (int z = 0; z < e.nz; z += 5)
      for (int y = 0; y < e.ny; y += 5)
        for (int x = 0; x < e.nx; x += 5) request.probes.emplace_back(x, y, z);
    const SurfacePieces got = m.solver->surfacePieces(request);
    const BandField field = m.solver->field();
    const SurfacePieces expected = listSurfacePieces(field, request, &m.target);
    expectSamePieces(got, expected);
    EXPECT_EQ(got.probeValues, expected.probeValues);
    EXPECT_EQ(got.probeValues.size(), request.probes.size());
    ASSERT_TRUE(got.errorNearBase);
    EXPECT_EQ(*got.errorNearBase, *expected.errorNearBase);
    EXPECT_GT(*got.errorNearBase, 0.5) << "the morph has a way to go";
    // Assembled: extractSurface()'s mesh (the sphere leaves the grid: an
    // open one), the same vertices in the same order, the same triangles.
    const GridFrame frame{glm::dvec3(0.0), 1.0, field.extent()};
    const TriangleMesh mesh = assembleSurface(got, frame), cpu = extractSurface(field, frame);
    EXPECT_EQ(mesh.vertexCount(), cpu.vertexCount());
    EXPECT_EQ(mesh.triangleCount(), cpu.triangleCount());
    EXPECT_EQ(mesh.positions, cpu.positions);
    EXPECT_EQ(mesh.triangles, cpu.triangles);
  }
}

// Another isovalue, no error asked for, and lists that outgrow the room the
// pass first makes (a rough field cuts many edges a brick): it runs again.
TEST_F(BandSurfacePass, ARoughFieldAndAnotherIsovalue)
{
  Morph m = startMorph(7.0, 4.0f);
  m.solver->step(1);
  const SurfacePieces got = m.solver->surfacePieces({.isovalue = 0.25f});
  EXPECT_FALSE(got.errorNearBase);
  expectSamePieces(got, listSurfacePieces(m.solver->field(), {.isovalue = 0.25f}));
  EXPECT_GT(got.crossings.size(), 16 * m.solver->bricks().activeCount()) << "more than the first room";
}

// A frame's pieces then a step, in one pass, as fieldIntoThenStep(): the
// pieces of the field it would read, and the same state after.
TEST_F(BandSurfacePass, PiecesThenAStepAreTheFieldsThenTheSameStep)
{
  Morph a = startMorph(7.0, 0.3f), b = startMorph(7.0, 0.3f);
  for (int frame = 0; frame < 4; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    const SurfacePieces got = a.solver->surfacePiecesThenStep({.nearBand = 1.0f}, SourceStrength{0.2f, 0.2f});
    BandField field;
    b.solver->fieldIntoThenStep(field, SourceStrength{0.2f, 0.2f});
    const SurfacePieces expected = listSurfacePieces(field, {.nearBand = 1.0f}, &b.target);
    expectSamePieces(got, expected);
    EXPECT_EQ(*got.errorNearBase, *expected.errorNearBase);
    a.solver->step(2);
    b.solver->step(2);
  }
  EXPECT_EQ(a.solver->stepsTaken(), b.solver->stepsTaken());
  EXPECT_EQ(a.solver->field().values(), b.solver->field().values());
}

// The reference solver's pieces are listSurfacePieces() of its field and its
// source's base: what the device's are held to.
TEST_F(BandSurfacePass, TheReferenceListsItsOwnField)
{
  Morph m = startMorph(7.0, 0.3f, Backend::Reference);
  m.solver->step(3);
  const SurfacePieces got = m.solver->surfacePieces({.nearBand = 1.0f});
  const SurfacePieces expected = listSurfacePieces(m.solver->field(), {.nearBand = 1.0f}, &m.target);
  expectSamePieces(got, expected);
  EXPECT_EQ(*got.errorNearBase, *expected.errorNearBase);
}

TEST_F(BandSurfacePass, AFieldThatIsNotFiniteIsANumericalError)
{
  const Extent3 extent{20, 20, 20};
  const Volume field = testing::sphereDistance(extent, 9.6, 10.2, 9.9, 6.3);
  auto bricks = testing::bricksNear(field, 4.0);
  auto solver = testing::makeBandSolver(Backend::Vulkan, bricks);
  solver->setUniformGamma(0.2);
  BandField start = testing::bandOf(field, bricks);
  start.values()[start.values().size() / 3] = std::numeric_limits<float>::infinity();
  solver->initialize(start, 100.0);  // every cell streams: a step updates every brick, in one pass with the pieces
  solver->step(2);
  EXPECT_THROW(solver->surfacePieces({}), NumericalError);
  // In one pass with a step: the step is taken all the same.
  EXPECT_THROW(solver->surfacePiecesThenStep({}, std::nullopt), NumericalError);
  EXPECT_EQ(solver->stepsTaken(), 3);
}

// A new start on the same bricks with other far sides (the inside turned
// out) and another source: the pass reads the new ones.
TEST_F(BandSurfacePass, ANewStartIsListedWithItsOwnFarSidesAndSource)
{
  Morph m = startMorph(1.0, 0.3f);
  m.solver->step(2);
  const SurfacePieces before = m.solver->surfacePieces({.nearBand = 1.0f});
  BandField turned = m.solver->field();
  for (float& v : turned.values()) v = -v;
  for (int8_t& side : turned.farSides()) side = int8_t(-side);
  BandField target = m.target;
  for (float& v : target.values()) v = -v;
  m.solver->setSource(BandSource{target, 0.1f, 0.1f});
  m.solver->initialize(turned, 1.0);
  m.solver->step(2);
  const SurfacePieces got = m.solver->surfacePieces({.nearBand = 1.0f});
  const SurfacePieces expected = listSurfacePieces(m.solver->field(), {.nearBand = 1.0f}, &target);
  expectSamePieces(got, expected);
  EXPECT_EQ(*got.errorNearBase, *expected.errorNearBase);
  ASSERT_FALSE(got.cubes.empty());
  EXPECT_NE(got.cubes[0].cubeCase, before.cubes[0].cubeCase) << "the inside turned out";
}

// Which frames a morph on the band lists on the device:
// ComputeDevice::surfacesOnTheDevice.
TEST(SurfacesOnTheDevice, AutoTakesTheCpuOnACpuDeviceAndEitherWhenForced)
{
  const ComputeDevice automatic("", false), cpu("", false, RunsOn::Auto, RunsOn::Cpu),
      device("", false, RunsOn::Auto, RunsOn::Device);
  EXPECT_EQ(automatic.surfacesOnTheDevice(), automatic.gpu()->description().type != "cpu");
  EXPECT_FALSE(cpu.surfacesOnTheDevice());
  EXPECT_TRUE(device.surfacesOnTheDevice());
  EXPECT_FALSE(ComputeDevice("reference", false).surfacesOnTheDevice());
  EXPECT_THROW(ComputeDevice("reference", false, RunsOn::Auto, RunsOn::Device).surfacesOnTheDevice(), UsageError);
}

}  // namespace
}  // namespace lbmshape
