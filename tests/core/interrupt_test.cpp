// The stop flag as a library's host sees it: a request of the program's own
// and SIGINT lent for the length of a call, the host's handler given back.
#include <signal.h>

#include <atomic>
#include <future>
#include <stop_token>
#include <string>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/core/worker_threads.hpp"

namespace lbmshape {
namespace {

std::atomic<int> hostSigints{0};
extern "C" void hostHandler(int) { ++hostSigints; }

// A host's SIGINT handler in place for a test, the previous one back after.
class HostHandler {
public:
  explicit HostHandler(void (*handler)(int))
  {
    struct sigaction action = {};
    action.sa_handler = handler;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_);
  }
  ~HostHandler()
  {
    sigaction(SIGINT, &previous_, nullptr);
    interrupt::clearStopRequest();
  }

private:
  struct sigaction previous_ = {};
};

TEST(StopRequest, TheProgramsRequestStopsTheNextCheckUntilCleared)
{
  interrupt::clearStopRequest();
  EXPECT_NO_THROW(interrupt::check("nothing"));
  interrupt::requestStop();
  EXPECT_TRUE(interrupt::requested());
  EXPECT_EQ(interrupt::signalReceived(), 0);
  try {
    interrupt::check("2 of 5 frames");
    FAIL() << "no stop";
  } catch (const Interrupted& e) {
    EXPECT_STREQ(e.what(), "stopped: 2 of 5 frames");
    EXPECT_EQ(e.signal(), 0);
    EXPECT_EQ(e.code(), ExitCode::Interrupted);
  }
  EXPECT_THROW(interrupt::check("again"), Interrupted);  // it stands
  interrupt::clearStopRequest();
  EXPECT_FALSE(interrupt::requested());
  EXPECT_NO_THROW(interrupt::check("nothing"));
}

// A call's own token stops that call: its thread's checks, and the threads
// it lends work to through a Watch, but no other thread's.
TEST(CallStop, ACallsTokenStopsThatCallAndTheThreadsItLendsWorkTo)
{
  interrupt::clearStopRequest();
  std::stop_source cancel;
  {
    const interrupt::CallStop call(cancel.get_token());
    EXPECT_FALSE(interrupt::requested());
    cancel.request_stop();
    EXPECT_TRUE(interrupt::requested());
    try {
      interrupt::check("nothing was written");
      ADD_FAILURE() << "no stop";
    } catch (const Interrupted& e) {
      EXPECT_EQ(std::string(e.what()), "stopped: nothing was written");
      EXPECT_EQ(e.signal(), 0);
    }
    const interrupt::Watch watch;
    EXPECT_TRUE(std::async(std::launch::async, [&] { return watch.requested(); }).get());
    EXPECT_FALSE(std::async(std::launch::async, [] { return interrupt::requested(); }).get()) << "another call's";
    EXPECT_TRUE(std::async(std::launch::async, [&] {
                  const interrupt::CallStop carried(watch);
                  return interrupt::requested();
                }).get());
    bool sawItThere = false;
    runSideBySide([] {}, [&] { sawItThere = interrupt::requested(); });
    EXPECT_TRUE(sawItThere) << "runSideBySide's second thread does the call's work";
    {
      const interrupt::CallStop nested{std::stop_token{}};  // a call within, given no token of its own
      EXPECT_TRUE(interrupt::requested());
    }
  }
  EXPECT_FALSE(interrupt::requested()) << "the call ended";
  EXPECT_NO_THROW(interrupt::check("nothing"));
}

TEST(SigintStopsCalls, SigintStopsTheCallAndTheHostGetsItsHandlerBack)
{
  HostHandler host(hostHandler);
  hostSigints = 0;
  {
    interrupt::SigintStopsCalls lent;
    EXPECT_FALSE(lent.caughtOne());
    raise(SIGINT);
    raise(SIGINT);  // a second is a request too: the host lives on
    EXPECT_TRUE(lent.caughtOne());
    EXPECT_EQ(hostSigints, 0);
    EXPECT_EQ(interrupt::signalReceived(), SIGINT);
    EXPECT_THROW(interrupt::check("a frame"), Interrupted);
  }
  raise(SIGINT);
  EXPECT_EQ(hostSigints, 1) << "the host's handler is back";
}

TEST(SigintStopsCalls, AHostThatIgnoresSigintKeepsIgnoringIt)
{
  HostHandler host(SIG_IGN);
  interrupt::clearStopRequest();
  interrupt::SigintStopsCalls lent;
  raise(SIGINT);
  EXPECT_FALSE(lent.caughtOne());
  EXPECT_FALSE(interrupt::requested());
}

}  // namespace
}  // namespace lbmshape
