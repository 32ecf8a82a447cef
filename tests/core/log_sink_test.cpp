// A program's log sink: the messages the level lets through go to it
// instead of stderr, each with its kind and without stderr's prefixes;
// warnings still reach a call's report; a message the sink logs itself goes
// to stderr; an empty sink restores stderr.
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "lbmshape/core/log.hpp"
#include "support/captured_stderr.hpp"

namespace lbmshape {
namespace {

using testing::CapturedStderr;

// Sets the level and sink for a test, and restores stderr and Normal after.
class LogSink : public ::testing::Test {
protected:
  ~LogSink() override
  {
    log::setSink({});
    log::setLevel(log::Level::Normal);
  }
  std::vector<std::pair<log::Kind, std::string>> received;
  log::Sink collect = [this](log::Kind kind, const std::string& message) { received.emplace_back(kind, message); };
};

TEST_F(LogSink, TakesWhatTheLevelLetsThroughInsteadOfStderr)
{
  const CapturedStderr err;
  log::setSink(collect);
  log::setLevel(log::Level::Normal);
  log::info("an info line");
  log::verbose("a verbose line");  // filtered by the level, as on stderr
  log::warning("a warning");
  log::progress("sdf  50%");
  const std::vector<std::pair<log::Kind, std::string>> expected = {
      {log::Kind::Info, "an info line"}, {log::Kind::Warning, "a warning"}, {log::Kind::Progress, "sdf  50%"}};
  EXPECT_EQ(received, expected);
  log::setLevel(log::Level::Verbose);
  log::verbose("a verbose line");
  ASSERT_EQ(received.size(), 4u);
  EXPECT_EQ(received.back(), std::pair(log::Kind::Verbose, std::string("a verbose line")));
  EXPECT_EQ(err.text(), "") << "nothing on stderr";
}

TEST_F(LogSink, WarningsStillReachTheCallsReport)
{
  const CapturedStderr err;
  log::setSink(collect);
  const log::WarningCollector report;
  log::warning("the result lost a part");
  EXPECT_EQ(report.warnings(), std::vector<std::string>{"the result lost a part"});
  ASSERT_EQ(received.size(), 1u);
}

TEST_F(LogSink, WhatTheSinkLogsGoesToStderrAndAnEmptySinkRestoresIt)
{
  const CapturedStderr err;
  log::setSink([this](log::Kind kind, const std::string& message) {
    received.emplace_back(kind, message);
    log::info("the sink's own line");  // would recurse forever
  });
  log::info("first");
  ASSERT_EQ(received.size(), 1u);
  EXPECT_EQ(err.text(), "lbmshape: the sink's own line\n");
  log::setSink({});
  log::warning("second");
  EXPECT_EQ(received.size(), 1u);
  EXPECT_EQ(err.text(), "lbmshape: the sink's own line\nlbmshape: warning: second\n");
}

TEST_F(LogSink, ASinkThatThrowsLosesTheLineNotTheCall)
{
  const CapturedStderr err;
  log::setSink([](log::Kind, const std::string&) { throw std::runtime_error("the host's logger failed"); });
  EXPECT_NO_THROW(log::warning("a warning"));
}

}  // namespace
}  // namespace lbmshape
