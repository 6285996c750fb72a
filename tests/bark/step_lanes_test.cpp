// The bark passes' lanes (step_lanes.h): every chunk of every pass runs exactly once, with or
// without the worker, for chunk counts from one to more than the claim word's halves hold at
// once, and after the worker has gone to sleep between passes; a chunk's writes are seen once Run
// returns.
#include "bark/step_lanes.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace niwa::bark {
namespace {

void ExpectEveryChunkOnce(int lanes, int passes, bool pause_between) {
  StepLanes step_lanes(lanes);
  EXPECT_EQ(step_lanes.threaded(), lanes == 2 && StepLanesHaveThreads());
  std::vector<std::atomic<int>> runs(200);
  std::vector<int> value(200);
  for (int pass = 0; pass < passes; ++pass) {
    const int chunks = 1 + (pass * 37) % 200;
    for (auto& r : runs) r.store(0);
    step_lanes.Run(chunks, [&](int k) {
      runs[k].fetch_add(1);
      value[k] = pass * 1000 + k;  // a plain write, read here after Run
    });
    for (int k = 0; k < 200; ++k) {
      ASSERT_EQ(runs[k].load(), k < chunks ? 1 : 0) << "pass " << pass << " chunk " << k;
      if (k < chunks) {
        ASSERT_EQ(value[k], pass * 1000 + k);
      }
    }
    // Long enough for an idle worker to stop spinning and yielding and sleep (step_lanes.cpp).
    if (pause_between && pass % 5 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(4));
  }
}

TEST(StepLanes, OneLaneRunsEveryChunkOnce) { ExpectEveryChunkOnce(1, 50, false); }

TEST(StepLanes, TwoLanesRunEveryChunkOnce) { ExpectEveryChunkOnce(2, 3000, false); }

TEST(StepLanes, AWorkerAsleepBetweenPassesStillShares) { ExpectEveryChunkOnce(2, 40, true); }

// The worker does take chunks (where the build has threads): over passes of chunks that take
// 20 µs each, long enough for the worker to be scheduled, some chunk ran off this thread.
TEST(StepLanes, TheWorkerTakesChunks) {
  if (!StepLanesHaveThreads()) GTEST_SKIP() << "no threads in this build";
  StepLanes step_lanes(2);
  const std::thread::id here = std::this_thread::get_id();
  std::atomic<int> elsewhere{0};
  for (int pass = 0; pass < 200 && elsewhere.load() == 0; ++pass) {
    step_lanes.Run(64, [&](int) {
      if (std::this_thread::get_id() != here) elsewhere.fetch_add(1);
      std::this_thread::sleep_for(std::chrono::microseconds(20));
    });
  }
  EXPECT_GT(elsewhere.load(), 0);
}

}  // namespace
}  // namespace niwa::bark
