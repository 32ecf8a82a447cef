#include "lbmshape/core/worker_threads.hpp"

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>
#include <omp.h>

namespace lbmshape {
namespace {

// The threads a parallel region of the calling thread gets.
int regionThreads()
{
  int threads = 0;
#pragma omp parallel
  {
#pragma omp single
    threads = omp_get_num_threads();
  }
  return threads;
}

// Both run, on two threads, at once (each waits to see the other start),
// each with half the caller's threads for its parallel regions (one each
// of two); the caller's regions get their threads back.
void expectSideBySideWithHalfTheThreadsEach(int threads, int expectedHere, int expectedThere)
{
  omp_set_num_threads(threads);
  std::atomic<int> started{0};
  int hereThreads = 0, thereThreads = 0;
  std::thread::id hereId, thereId;
  const auto meet = [&] {
    ++started;
    while (started.load() < 2) std::this_thread::yield();
  };
  runSideBySide(
      [&] {
        meet();
        hereId = std::this_thread::get_id();
        hereThreads = regionThreads();
      },
      [&] {
        meet();
        thereId = std::this_thread::get_id();
        thereThreads = regionThreads();
      });
  EXPECT_EQ(hereId, std::this_thread::get_id());
  EXPECT_NE(thereId, hereId);
  EXPECT_EQ(hereThreads, expectedHere) << "of " << threads;
  EXPECT_EQ(thereThreads, expectedThere) << "of " << threads;
  EXPECT_EQ(omp_get_max_threads(), threads);
  EXPECT_EQ(regionThreads(), threads);
}

TEST(RunSideBySide, RunsBothAtOnceWithHalfTheThreadsEach)
{
  const int before = omp_get_max_threads();
  expectSideBySideWithHalfTheThreadsEach(2, 1, 1);
  expectSideBySideWithHalfTheThreadsEach(1, 1, 1);
  expectSideBySideWithHalfTheThreadsEach(5, 3, 2);
  expectSideBySideWithHalfTheThreadsEach(8, 4, 4);
  omp_set_num_threads(before);
}

// An exception from either reaches the caller, after both have ended; the
// caller's regions get their threads back.
TEST(RunSideBySide, AnExceptionFromEitherReachesTheCallerWhenBothEnded)
{
  omp_set_num_threads(2);
  std::atomic<bool> thereEnded{false};
  EXPECT_THROW(runSideBySide([] { throw std::runtime_error("here"); },
                             [&] {
                               std::this_thread::sleep_for(std::chrono::milliseconds(50));
                               thereEnded = true;
                             }),
               std::runtime_error);
  EXPECT_TRUE(thereEnded.load());
  EXPECT_EQ(omp_get_max_threads(), 2);
  bool hereRan = false;
  EXPECT_THROW(runSideBySide([&] { hereRan = true; }, [] { throw std::logic_error("there"); }), std::logic_error);
  EXPECT_TRUE(hereRan);
  EXPECT_EQ(omp_get_max_threads(), 2);
}

}  // namespace
}  // namespace lbmshape
