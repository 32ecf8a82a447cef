// A stop before a stage says what the job has completed, as the job
// describes it; without a description, the stage it stopped before.
#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/pipeline/stage_clock.hpp"

namespace lbmshape {
namespace {

std::string stopMessage(StageClock& clock)
{
  interrupt::requestStop();
  std::string message;
  try {
    clock.time("relax", [] {});
  } catch (const Interrupted& e) {
    message = e.what();
  }
  interrupt::clearStopRequest();
  return message;
}

TEST(StageClock, AStopSaysWhatIsComplete)
{
  StageClock clock;
  EXPECT_EQ(stopMessage(clock), "stopped: before the relax stage");
  clock.describeProgressWith([] { return std::string("nothing was written"); });
  EXPECT_EQ(stopMessage(clock), "stopped: nothing was written");
  bool ran = false;
  clock.time("relax", [&] { ran = true; });  // no stop requested: it runs
  EXPECT_TRUE(ran);
}

}  // namespace
}  // namespace lbmshape
