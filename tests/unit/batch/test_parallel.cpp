// The batch jobs' parallel loop: every index once, the cyclic schedule's worker assignment, the
// calling thread's part, progress, and exceptions rethrown deterministically.

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "batch/parallel.hpp"

namespace rollcontact::batch {
namespace {

TEST(ParallelFor, VisitsEveryIndexExactlyOnce) {
  for (std::size_t n : {0u, 1u, 3u, 17u, 200u})
    for (int threads : {-1, 0, 1, 2, 5, 300})
      for (Schedule schedule : {Schedule::Cyclic, Schedule::Dynamic}) {
        std::vector<std::atomic<int>> visits(n);
        parallel_for(n, {threads, schedule}, [&](std::size_t, std::size_t i) { ++visits[i]; });
        for (std::size_t i = 0; i < n; ++i)
          EXPECT_EQ(visits[i].load(), 1) << "n " << n << " threads " << threads << " index " << i;
      }
}

TEST(ParallelFor, CyclicScheduleGivesIndexIToWorkerIModWorkers) {
  const std::size_t n = 23;
  std::vector<std::size_t> worker_of(n, 99);
  std::vector<std::vector<std::size_t>> order(3);
  std::mutex mutex;
  parallel_for(n, {3, Schedule::Cyclic}, [&](std::size_t w, std::size_t i) {
    const std::lock_guard<std::mutex> lock(mutex);
    worker_of[i] = w;
    order[w].push_back(i);
  });
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(worker_of[i], i % 3) << i;
  for (const auto& o : order) EXPECT_TRUE(std::is_sorted(o.begin(), o.end()));  // increasing
  // More workers than indices: one index each.
  std::vector<std::size_t> w2(2, 99);
  parallel_for(2, {8, Schedule::Cyclic}, [&](std::size_t w, std::size_t i) { w2[i] = w; });
  EXPECT_EQ(w2[0], 0u);
  EXPECT_EQ(w2[1], 1u);
}

TEST(ParallelFor, WorkerCountIsTheRequestClampedToTheWork) {
  EXPECT_EQ(worker_count(23, 3), 3u);
  EXPECT_EQ(worker_count(2, 8), 2u);
  EXPECT_EQ(worker_count(5, 0), 1u);
  EXPECT_EQ(worker_count(5, -2), 1u);
  EXPECT_EQ(worker_count(0, 4), 1u);
}

TEST(ParallelFor, OneWorkerRunsOnTheCallingThread) {
  const auto caller = std::this_thread::get_id();
  bool same = true;
  parallel_for(5, {1, Schedule::Dynamic},
               [&](std::size_t, std::size_t) { same &= std::this_thread::get_id() == caller; });
  EXPECT_TRUE(same);
}

TEST(ParallelFor, ProgressEndsWithTheCountOfFinishedIndices) {
  const auto caller = std::this_thread::get_id();
  std::vector<std::size_t> reports;
  bool on_caller = true;
  parallel_for(
      50, {2, Schedule::Cyclic}, [](std::size_t, std::size_t) {},
      [&](std::size_t done) {
        reports.push_back(done);
        on_caller &= std::this_thread::get_id() == caller;
      });
  ASSERT_FALSE(reports.empty());
  EXPECT_EQ(reports.back(), 50u);
  EXPECT_TRUE(std::is_sorted(reports.begin(), reports.end()));
  EXPECT_TRUE(on_caller);
}

TEST(ParallelFor, RethrowsTheExceptionOfTheLowestIndexAfterTheOthersFinished) {
  for (int threads : {1, 2, 4}) {
    std::atomic<int> finished{0};
    try {
      parallel_for(40, {threads, Schedule::Dynamic}, [&](std::size_t, std::size_t i) {
        if (i == 7 || i == 31) throw std::runtime_error("index " + std::to_string(i));
        ++finished;
      });
      ADD_FAILURE() << "no exception with " << threads << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "index 7") << threads << " threads";
    }
    // One worker stops at the first failure; with four, the two that fail stop and the other
    // two take every index that is left (dynamic schedule).
    if (threads == 1) {
      EXPECT_EQ(finished.load(), 7);
    }
    if (threads == 4) {
      EXPECT_EQ(finished.load(), 38);
    }
  }
}

}  // namespace
}  // namespace rollcontact::batch
