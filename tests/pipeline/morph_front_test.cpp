#include "lbmshape/pipeline/morph_front.hpp"

#include <gtest/gtest.h>

#include "lbmshape/lbm/frozen_bricks.hpp"
#include "lbmshape/pipeline/morph.hpp"
#include "support/band_fields.hpp"

namespace lbmshape {
namespace {

// A plane front moving along x from x = 8 (the source's zero level) to
// x = 40 (the target's), on a row of seven bricks: where it passes, when.
struct PlaneFront {
  Extent3 extent{56, 8, 8};
  std::shared_ptr<BrickSet> bricks;
  BandField source, target;
  std::vector<uint8_t> streams;
  MorphSchedule schedule = fortySteps();

  PlaneFront()
  {
    Volume a(extent), t(extent);
    for (int z = 0; z < extent.nz; ++z)
      for (int y = 0; y < extent.ny; ++y)
        for (int x = 0; x < extent.nx; ++x) {
          a.at(x, y, z) = float(x) - 8.0f;
          t.at(x, y, z) = float(x) - 40.0f;
        }
    bricks = testing::bricksNear(a, 100.0);
    source = testing::bandOf(a, bricks);
    target = testing::bandOf(t, bricks);
    streams.assign(source.values().size(), 1);
  }
  static MorphSchedule fortySteps()
  {
    MorphOptions o;
    o.steps = 40;
    return MorphSchedule::fixed(o);
  }
  size_t slotAt(int x) const { return size_t(bricks->slot(x / brickEdge, 0, 0)); }
};

TEST(MorphFront, BricksStreamWhileThePredictedSurfaceIsNear)
{
  const PlaneFront plane;
  ASSERT_EQ(plane.bricks->activeCount(), 7u);
  const MorphFront front(plane.source, plane.target, plane.streams, 3.0, plane.schedule);
  const int total = plane.schedule.totalSteps();
  std::vector<int> firstStreaming(7, -1), lastStreaming(7, -1);
  for (int n = 0; n < total; ++n) {
    const std::vector<uint8_t> held = front.heldDuring(n);
    ASSERT_EQ(held.size(), 7u);
    for (int b = 0; b < 7; ++b)
      if (!held[plane.slotAt(b * brickEdge)]) {
        if (firstStreaming[size_t(b)] < 0) firstStreaming[size_t(b)] = n;
        lastStreaming[size_t(b)] = n;
      }
  }
  // The source's surface (x = 8) is near bricks 0 and 1 at the start only.
  EXPECT_EQ(firstStreaming[0], 0);
  EXPECT_EQ(firstStreaming[1], 0);
  EXPECT_LT(lastStreaming[0], total / 4);
  // The front reaches the bricks on its way in order, and leaves those it
  // has passed (x < 37, more than 3 voxels from the target's surface).
  for (int b = 2; b <= 5; ++b) EXPECT_GT(firstStreaming[size_t(b)], firstStreaming[size_t(b) - 1]) << "brick " << b;
  for (int b = 2; b <= 3; ++b) EXPECT_LT(lastStreaming[size_t(b)], total - 1) << "brick " << b;
  // The target's surface (x = 40) lies between bricks 4 and 5, which
  // stream at the end; X >= 8 in brick 6 (x >= 48) all the way, which never
  // streams.
  EXPECT_EQ(lastStreaming[4], total - 1);
  EXPECT_EQ(lastStreaming[5], total - 1);
  EXPECT_EQ(firstStreaming[6], -1);
  EXPECT_GT(front.meanStreamingFraction(), 0.0);
  EXPECT_LT(front.meanStreamingFraction(), 0.5);
}

// A frozen brick is one that no step reads: none of its 27 bricks streams
// in that step or the next; those near the target's surface never freeze;
// the others freeze where the front is far.
TEST(MorphFront, FrozenBricksAreFarFromEveryStreamingOne)
{
  const PlaneFront plane;
  const MorphFront front(plane.source, plane.target, plane.streams, 3.0, plane.schedule);
  const int total = plane.schedule.totalSteps();
  const std::vector<int32_t> around = plane.bricks->neighbourTable();
  int frozenSteps = 0;
  for (int n = 0; n < total; ++n) {
    const std::vector<uint8_t> now = front.heldDuring(n),
                               next = n + 1 < total ? front.heldDuring(n + 1) : std::vector<uint8_t>(7, 1);
    for (size_t s = 0; s < 7; ++s) {
      if (now[s] != uint8_t(BrickMotion::Frozen)) continue;
      ++frozenSteps;
      EXPECT_NE(s, plane.slotAt(39)) << "near the target, step " << n;
      EXPECT_NE(s, plane.slotAt(40)) << "near the target, step " << n;
      for (int k = 0; k < 27; ++k) {
        const int32_t b = around[s * 27 + size_t(k)];
        if (b == noBrick) continue;
        EXPECT_NE(now[size_t(b)], uint8_t(BrickMotion::Streams)) << "slot " << s << ", step " << n;
        EXPECT_NE(next[size_t(b)], uint8_t(BrickMotion::Streams)) << "slot " << s << ", step " << n;
      }
    }
  }
  // Brick 6 (x >= 48) all the way, brick 0 once the front has left it.
  EXPECT_GT(frozenSteps, total);
  EXPECT_GT(front.meanFrozenFraction(), 0.0);
}

// The steps up to sameUntil() hold the same bricks: the morph runs them as
// one batch; the step it names holds others.
TEST(MorphFront, HeldBricksChangeOnlyWhereSameUntilSays)
{
  const PlaneFront plane;
  const MorphFront front(plane.source, plane.target, plane.streams, 3.0, plane.schedule);
  const int total = plane.schedule.totalSteps();
  int changes = 0;
  for (int n = 0; n < total;) {
    const int until = front.sameUntil(n);
    ASSERT_GT(until, n);
    for (int m = n + 1; m < std::min(until, total); ++m) EXPECT_EQ(front.heldDuring(m), front.heldDuring(n));
    if (until < total) {
      EXPECT_NE(front.heldDuring(until), front.heldDuring(n)) << "step " << until;
      ++changes;
    }
    n = until;
  }
  EXPECT_GE(changes, 5);
}

// Cells that never stream (initialize()'s flags) make no brick stream: all
// are frozen, but for the two with cells within 2 voxels of the target's
// surface (x = 40), which are held.
TEST(MorphFront, OnlyCellsThatMayStreamCount)
{
  PlaneFront plane;
  std::fill(plane.streams.begin(), plane.streams.end(), 0);
  const MorphFront front(plane.source, plane.target, plane.streams, 3.0, plane.schedule);
  std::vector<uint8_t> expected(7, uint8_t(BrickMotion::Frozen));
  expected[plane.slotAt(39)] = expected[plane.slotAt(40)] = uint8_t(BrickMotion::Held);
  for (int n = 0; n < plane.schedule.totalSteps(); ++n) EXPECT_EQ(front.heldDuring(n), expected) << "step " << n;
  EXPECT_EQ(front.meanStreamingFraction(), 0.0);
  EXPECT_NEAR(front.meanFrozenFraction(), 5.0 / 7.0, 1e-12);
  EXPECT_THROW(MorphFront(plane.source, plane.target, plane.streams, 0.0, plane.schedule), std::invalid_argument);
}

}  // namespace
}  // namespace lbmshape
