// The progress line of long stages: silent for short ones and with --quiet,
// a line saying how far the stage is once it has run past the delay.
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "lbmshape/core/log.hpp"
#include "support/captured_stderr.hpp"
#include "lbmshape/core/progress.hpp"
#include "lbmshape/core/stopwatch.hpp"

namespace lbmshape {
namespace {

using testing::CapturedStderr;

class ProgressLine : public ::testing::Test {
protected:
  void SetUp() override { log::setLevel(log::Level::Normal); }
  void TearDown() override
  {
    unsetenv("LBMSHAPE_PROGRESS_MS");
    log::setLevel(log::Level::Normal);
  }
  static void sleepMs(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }
  // Whether the progress's reporter has written a line within 10 s, however
  // busy the machine.
  static bool waitForALine(const Progress& p)
  {
    for (Stopwatch waited; !p.lineShown() && waited.ms() < 10000.0;) sleepMs(5);
    return p.lineShown();
  }
};

TEST_F(ProgressLine, WeightedPartsAddUpToTheWholeStage)
{
  Progress p("sdf");
  EXPECT_DOUBLE_EQ(p.fraction(), 0.0);
  p.beginPart("band", 10, 0.25);
  p.advance(5);
  EXPECT_DOUBLE_EQ(p.fraction(), 0.125);
  p.beginPart("sign", 4, 0.75);
  EXPECT_DOUBLE_EQ(p.fraction(), 0.25) << "the finished part counts whole";
  p.advance(2);
  EXPECT_DOUBLE_EQ(p.fraction(), 0.625);
  p.advance(100);
  EXPECT_DOUBLE_EQ(p.fraction(), 1.0) << "never past the end";
}

TEST_F(ProgressLine, AdvancesFromManyThreadsAddUp)
{
  Progress p("lbm");
  p.beginPart("steps", 4000);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      for (int i = 0; i < 1000; ++i) p.advance();
    });
  for (auto& t : threads) t.join();
  EXPECT_DOUBLE_EQ(p.fraction(), 1.0);
}

TEST_F(ProgressLine, ShortStageSaysNothing)
{
  CapturedStderr err;
  {
    Progress p("sdf");
    p.beginPart("band", 1);
    p.advance();
  }
  EXPECT_EQ(err.text(), "") << "the default delay is a second";
}

TEST_F(ProgressLine, LongStageSaysHowFarItIs)
{
  setenv("LBMSHAPE_PROGRESS_MS", "20", 1);
  CapturedStderr err;
  {
    Progress p("lbm");
    p.beginPart("steps", 4);
    p.advance(1);
    // The reporter writes after 20 ms; however busy the machine, wait for it.
    ASSERT_TRUE(waitForALine(p));
  }
  const std::string text = err.text();
  EXPECT_NE(text.find("lbmshape: lbm  25% (steps)"), std::string::npos) << text;
}

// At a short interval, a line the same as the last is not written again
// (one changes with its percentage, its part or its tenth of a second):
// LBMSHAPE_PROGRESS_MS=0 wrote 1,591 lines for a 2 s denoise, most of them
// repeats.
TEST_F(ProgressLine, ALineIsNotRepeated)
{
  setenv("LBMSHAPE_PROGRESS_MS", "1", 1);
  CapturedStderr err;
  {
    Progress p("lbm");
    p.beginPart("steps", 4);
    p.advance(1);
    ASSERT_TRUE(waitForALine(p));
    sleepMs(100);  // a hundred intervals without a step
    p.advance(1);
    sleepMs(100);
  }
  const std::string text = err.text();
  const auto count = [&](const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  // A line changes with its percentage or its tenth of a second: over
  // about 0.2 s, a few lines, where every millisecond's would be hundreds.
  EXPECT_GE(count("lbm  25% (steps)"), 1u) << text;
  EXPECT_GE(count("lbm  50% (steps)"), 1u) << text;
  EXPECT_LE(count("lbmshape: lbm"), 8u) << text;
}

TEST_F(ProgressLine, QuietMeansNoLine)
{
  setenv("LBMSHAPE_PROGRESS_MS", "1", 1);
  log::setLevel(log::Level::Quiet);
  CapturedStderr err;
  {
    Progress p("lbm");
    sleepMs(50);
  }
  EXPECT_EQ(err.text(), "");
}

// LBMSHAPE_PROGRESS_MS: a number of milliseconds, at most a day; what is
// not a finite number is ignored. (A huge value once made every wait of the
// reporter return at once: a stage never ended.)
TEST_F(ProgressLine, TheIntervalFromTheEnvironmentIsBounded)
{
  setenv("LBMSHAPE_PROGRESS_MS", "250", 1);
  EXPECT_EQ(ProgressTiming::current().firstMs, 250.0);
  setenv("LBMSHAPE_PROGRESS_MS", "0", 1);
  EXPECT_EQ(ProgressTiming::current().firstMs, 0.0);
  EXPECT_EQ(ProgressTiming::current().everyMs, 1.0);
  for (const char* huge : {"1e13", "inf", "99999999999999999999"}) {
    setenv("LBMSHAPE_PROGRESS_MS", huge, 1);
    EXPECT_LE(ProgressTiming::current().firstMs, 86400e3) << huge;
  }
  unsetenv("LBMSHAPE_PROGRESS_MS");
  const ProgressTiming unset = ProgressTiming::current();
  for (const char* bad : {"abc", "nan", "12ms", "", "-5"}) {
    setenv("LBMSHAPE_PROGRESS_MS", bad, 1);
    EXPECT_EQ(ProgressTiming::current().firstMs, unset.firstMs) << bad;
  }
  // A stage under a bound a day long ends at once.
  setenv("LBMSHAPE_PROGRESS_MS", "1e13", 1);
  const Stopwatch clock;
  {
    Progress progress("stage");
  }
  EXPECT_LT(clock.ms(), 60e3);
}

}  // namespace
}  // namespace lbmshape
