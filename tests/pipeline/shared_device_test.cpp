// Calls that share one ComputeDevice take turns (ComputeDevice::takeTurn):
// two threads' first calls on one device crashed in its warm-up, or hung,
// before they did. A call waiting for its turn still stops on request, and a
// morph's frame sink that calls on the morph's own device, which would wait
// for ever, is told so.
#include <chrono>
#include <future>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "lbmshape/core/error.hpp"
#include "lbmshape/core/interrupt.hpp"
#include "lbmshape/mesh/mesh_noise.hpp"
#include "lbmshape/pipeline/compute_device.hpp"
#include "lbmshape/pipeline/denoise.hpp"
#include "lbmshape/pipeline/morph.hpp"
#include "support/test_meshes.hpp"

namespace lbmshape {
namespace {

DenoiseOptions smallDenoise()
{
  DenoiseOptions o;
  o.grid.resolution = 32;
  return o;
}

TEST(SharedDevice, TwoThreadsFirstCallsOnOneDeviceGiveWhatOneThreadGets)
{
  const TriangleMesh noisy = addNormalNoise(testing::icosphere(3), 0.3, 5);
  const ComputeDevice alone{"", true};
  const TriangleMesh expected = denoiseMesh(noisy, "a noisy sphere", smallDenoise(), alone).mesh;
  // Twice, each on a device that neither thread has used: the warm-up of
  // a device's first call is where the two met.
  for (int round = 0; round < 2; ++round) {
    const ComputeDevice shared{"", true};
    auto call = [&] { return denoiseMesh(noisy, "a noisy sphere", smallDenoise(), shared).mesh; };
    std::future<TriangleMesh> first = std::async(std::launch::async, call),
                              second = std::async(std::launch::async, call);
    for (std::future<TriangleMesh>* result : {&first, &second}) {
      const TriangleMesh mesh = result->get();
      EXPECT_EQ(mesh.triangles, expected.triangles) << "round " << round;
      EXPECT_EQ(mesh.positions, expected.positions) << "round " << round;
    }
    shared.requireCleanValidation();
  }
}

TEST(SharedDevice, ACallWaitingForItsTurnStopsOnRequest)
{
  const ComputeDevice device{"", true};
  std::future<DenoiseResult> waiting;
  {
    const ComputeDevice::Turn held = device.takeTurn();  // another call's, for as long as this block lasts
    waiting = std::async(std::launch::async,
                         [&] { return denoiseMesh(testing::icosphere(3), "a sphere", smallDenoise(), device); });
    EXPECT_EQ(waiting.wait_for(std::chrono::milliseconds(300)), std::future_status::timeout) << "it did not wait";
    interrupt::requestStop();
    EXPECT_EQ(waiting.wait_for(std::chrono::seconds(10)), std::future_status::ready)
        << "the request did not end the wait";
  }
  try {
    waiting.get();
    ADD_FAILURE() << "the waiting call ran";
  } catch (const Interrupted& e) {
    EXPECT_NE(std::string(e.what()).find("waiting for the device"), std::string::npos) << e.what();
  }
  interrupt::clearStopRequest();
  EXPECT_NO_THROW(denoiseMesh(testing::icosphere(3), "a sphere", smallDenoise(), device));  // its turn is free
}

// Options and meshes are checked before the turn is taken: a bad call
// fails at once, not after the call that holds the device.
TEST(SharedDevice, ABadCallFailsWithoutWaitingForItsTurn)
{
  const ComputeDevice device{"", true};
  ComputeDevice::Turn held = device.takeTurn();  // another call's
  DenoiseOptions badGamma = smallDenoise();
  badGamma.gamma = -1;
  TriangleMesh badIndex = testing::icosphere(2);
  badIndex.triangles[0][0] = uint32_t(badIndex.vertexCount());
  std::future<void> gamma = std::async(std::launch::async, [&] {
    EXPECT_THROW(denoiseMesh(testing::icosphere(2), "a sphere", badGamma, device), UsageError);
  });
  std::future<void> index = std::async(std::launch::async, [&] {
    EXPECT_THROW(morphMeshes(badIndex, testing::icosphere(2), MorphOptions{}, device, [](int, const TriangleMesh&) {}),
                 InputError);
  });
  // Generous: without the checks first, they wait for as long as `held` is held.
  std::vector<std::future_status> ended;
  for (std::future<void>* call : {&gamma, &index}) ended.push_back(call->wait_for(std::chrono::seconds(60)));
  held.unlock();
  EXPECT_EQ(ended[0], std::future_status::ready) << "the bad denoise waited for its turn";
  EXPECT_EQ(ended[1], std::future_status::ready) << "the bad morph waited for its turn";
}

// A call's own stop (the options' token) stops it alone: a morph on another
// thread, on another device, makes all its frames meanwhile.
TEST(SharedDevice, AStopOfItsOwnStopsThatCallAlone)
{
  interrupt::clearStopRequest();
  const ComputeDevice one{"", true}, other{"", true};
  MorphOptions morph;
  morph.grid.resolution = 24;
  morph.align = Alignment::None;
  morph.frames = 6;
  morph.steps = 60;
  std::stop_source cancel;
  DenoiseOptions stopped = smallDenoise();
  stopped.stop = cancel.get_token();
  int frames = 0;
  std::future<void> running = std::async(std::launch::async, [&] {
    morphMeshes(testing::icosphere(3), testing::scaled(testing::icosphere(3), 0.7), morph, other,
                [&](int, const TriangleMesh&) { ++frames; });
  });
  cancel.request_stop();
  try {
    denoiseMesh(testing::icosphere(3), "a sphere", stopped, one);
    ADD_FAILURE() << "the stopped call ran";
  } catch (const Interrupted& e) {
    EXPECT_EQ(std::string(e.what()).rfind("stopped: ", 0), 0u) << e.what();
  }
  EXPECT_NO_THROW(running.get());
  EXPECT_EQ(frames, morph.frames);
  EXPECT_NO_THROW(denoiseMesh(testing::icosphere(3), "a sphere", smallDenoise(), one));  // the stop was that call's
}

TEST(SharedDevice, ACallFromAFrameSinkOnTheMorphsOwnDeviceIsAUsageError)
{
  const ComputeDevice device{"", true};
  MorphOptions o;
  o.grid.resolution = 32;
  o.align = Alignment::None;
  o.frames = 3;
  o.steps = 10;
  const TriangleMesh sphere = testing::icosphere(3), smaller = testing::scaled(testing::icosphere(3), 0.7);
  try {
    morphMeshes(sphere, smaller, o, device,
                [&](int, const TriangleMesh& frame) { denoiseMesh(frame, "a frame", smallDenoise(), device); });
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("a device of its own"), std::string::npos) << e.what();
  }
  // On a device of its own, the same call runs.
  const ComputeDevice other{"", true};
  int denoised = 0;
  morphMeshes(sphere, smaller, o, device, [&](int, const TriangleMesh& frame) {
    denoised += denoiseMesh(frame, "a frame", smallDenoise(), other).mesh.triangleCount() > 0;
  });
  EXPECT_EQ(denoised, o.frames);
}

TEST(SharedDevice, AnEmptyFrameSinkIsAUsageErrorNamingIt)
{
  const ComputeDevice device{"", true};
  try {
    morphMeshes(testing::icosphere(2), testing::scaled(testing::icosphere(2), 0.7), MorphOptions{}, device, {});
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("frame sink is empty"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lbmshape
