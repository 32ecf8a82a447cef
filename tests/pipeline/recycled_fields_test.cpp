#include "lbmshape/pipeline/recycled_fields.hpp"

#include <thread>

#include <gtest/gtest.h>

#include "lbmshape/core/volume.hpp"

namespace lbmshape {
namespace {

// A field let go comes back, with its memory, to the next take(); one still
// held is never handed out twice.
TEST(RecycledFields, AFieldLetGoIsTakenAgainAndOneHeldIsNot)
{
  RecycledFields<Volume> fields;
  std::shared_ptr<Volume> first = fields.take();
  *first = Volume(Extent3{8, 8, 8}, 2.0f);
  const float* memory = first->data();
  std::shared_ptr<Volume> second = fields.take();
  EXPECT_NE(second.get(), first.get());
  first.reset();
  std::shared_ptr<Volume> third = fields.take();
  EXPECT_EQ(third->data(), memory);
  EXPECT_EQ(third->at(7, 7, 7), 2.0f);  // as it was left: the taker overwrites it
}

// At most two idle fields stay: a third let go is freed, and those let go
// after the shelf's owner is gone are freed too (the sanitizer suites find
// a leak if not).
TEST(RecycledFields, KeepsAtMostTwoIdleFields)
{
  auto fields = std::make_unique<RecycledFields<Volume>>();
  std::vector<std::shared_ptr<Volume>> held;
  for (int k = 0; k < 4; ++k) held.push_back(fields->take());
  std::vector<const Volume*> addresses;
  for (auto& f : held) addresses.push_back(f.get());
  held.clear();  // back in order 0, 1, 2, 3: 0 and 1 kept
  std::shared_ptr<Volume> a = fields->take(), b = fields->take(), c = fields->take();
  EXPECT_EQ(a.get(), addresses[1]);
  EXPECT_EQ(b.get(), addresses[0]);
  EXPECT_NE(c.get(), addresses[0]);
  EXPECT_NE(c.get(), addresses[1]);
  fields.reset();
  a.reset(), b.reset(), c.reset();
}

// Fields come back on another thread (the frame writer's) while this one
// takes: each field is held by one owner at a time.
TEST(RecycledFields, FieldsComeBackFromAnotherThread)
{
  RecycledFields<Volume> fields;
  std::vector<std::shared_ptr<Volume>> handed(200);
  for (auto& f : handed) f = fields.take(), *f = Volume(Extent3{2, 2, 2}, 1.0f);
  std::thread writer([&handed] {
    for (auto& f : handed) f.reset();
  });
  std::vector<std::shared_ptr<Volume>> taken;
  for (int k = 0; k < 200; ++k) taken.push_back(fields.take());
  writer.join();
  std::vector<const Volume*> distinct;
  for (auto& f : taken) distinct.push_back(f.get());
  std::sort(distinct.begin(), distinct.end());
  EXPECT_EQ(std::unique(distinct.begin(), distinct.end()), distinct.end());
}

}  // namespace
}  // namespace lbmshape
