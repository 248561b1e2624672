#include "run/parallel_for.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <stdexcept>
#include <thread>
#include <vector>

#include "run/interrupt.hpp"

namespace swarmagg {
namespace {

TEST(ParallelFor, RunsEveryTaskOnceOnAnyThreadCount) {
  for (const int threads : {1, 2, 5, 64}) {
    std::vector<std::atomic<int>> runs(37);
    parallel_for(runs.size(), threads, [&](std::size_t i) { ++runs[i]; });
    for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].load(), 1) << i;
  }
  int calls = 0;
  parallel_for(0, 4, [&](std::size_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(ParallelFor, PassesOnTheFirstErrorAndStartsNoFurtherTask) {
  std::atomic<int> started{0};
  try {
    parallel_for(1000, 1, [&](std::size_t i) {
      ++started;
      if (i == 3) throw std::runtime_error("task 3");
      if (i == 4) throw std::logic_error("task 4");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "task 3");
  }
  EXPECT_EQ(started.load(), 4);  // tasks 0..3, in order on one thread
  EXPECT_THROW(parallel_for(100, 3, [](std::size_t) { throw std::runtime_error("x"); }),
               std::runtime_error);
}

TEST(ParallelFor, CallsTheWaitingCallbackOnTheCallingThreadUntilDone) {
  // The tasks hold until the callback has run, so it must run while they are under way
  // (otherwise fast tasks could end before the caller first looks, and the test would flake).
  std::atomic<bool> done{false};
  std::atomic<int> waits{0};
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> on_caller{true};
  parallel_for(
      2, 2,
      [&](std::size_t) {
        while (waits.load() == 0) std::this_thread::yield();
        done = true;
      },
      [&] {
        if (std::this_thread::get_id() != caller) on_caller = false;
        ++waits;
      });
  EXPECT_TRUE(done.load());
  EXPECT_GE(waits.load(), 1);
  EXPECT_TRUE(on_caller.load());
}

// A call's stop request (the Python module's Ctrl-C) reaches the workers of its pool, and no
// thread outside the call.
TEST(ParallelFor, CarriesTheCallersStopRequestToItsWorkersOnly) {
  std::atomic<int> request{SIGINT};
  std::vector<int> seen(8, -1);
  int outside = -1;
  {
    const InterruptScope scope(&request);
    parallel_for(seen.size(), 3, [&](std::size_t i) { seen[i] = interrupt_signal(); });
    std::thread([&] { outside = interrupt_signal(); }).join();
    EXPECT_EQ(interrupt_signal(), SIGINT);
  }
  for (const int signal : seen) EXPECT_EQ(signal, SIGINT);
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(interrupt_signal(), 0);  // the scope is closed
  parallel_for(seen.size(), 3, [&](std::size_t i) { seen[i] = interrupt_signal(); });
  for (const int signal : seen) EXPECT_EQ(signal, 0);
}

}  // namespace
}  // namespace swarmagg
