#include "batch/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

namespace rollcontact::batch {

namespace {

/// The first failure of one worker: its index and the exception.
struct Failure {
  std::size_t index = std::numeric_limits<std::size_t>::max();
  std::exception_ptr error;
};

}  // namespace

int default_thread_count(int requested) {
  if (requested > 0) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? static_cast<int>(hw) : 1;
}

std::size_t worker_count(std::size_t n, int threads) {
  return std::clamp<std::size_t>(threads < 1 ? 1 : static_cast<std::size_t>(threads), 1,
                                 std::max<std::size_t>(n, 1));
}

void parallel_for(std::size_t n, const ParallelOptions& options,
                  const std::function<void(std::size_t worker, std::size_t index)>& body,
                  const std::function<void(std::size_t done)>& progress) {
  if (n == 0) return;
  const std::size_t workers = worker_count(n, options.threads);
  std::atomic<std::size_t> next{0}, done{0}, finished{0};
  std::vector<Failure> failures(workers);
  std::mutex mutex;
  std::condition_variable cv;

  auto run_worker = [&](std::size_t w) {
    std::size_t i = 0;
    try {
      if (options.schedule == Schedule::Cyclic) {
        for (i = w; i < n; i += workers) {
          body(w, i);
          done.fetch_add(1);
        }
      } else {
        for (i = next++; i < n; i = next++) {
          body(w, i);
          done.fetch_add(1);
        }
      }
    } catch (...) {
      failures[w] = {i, std::current_exception()};
    }
    finished.fetch_add(1);
    const std::lock_guard<std::mutex> lock(mutex);
    cv.notify_one();
  };

  if (workers == 1 && !progress) {
    run_worker(0);
  } else {
    std::vector<std::jthread> threads;
    threads.reserve(workers);
    // Without a progress callback the calling thread is a worker itself.
    const std::size_t first_thread = progress ? 0 : 1;
    for (std::size_t w = first_thread; w < workers; ++w) threads.emplace_back(run_worker, w);
    if (progress) {
      std::unique_lock<std::mutex> lock(mutex);
      bool all_finished = false;
      while (!all_finished) {
        all_finished = cv.wait_for(lock, std::chrono::milliseconds(200),
                                   [&] { return finished.load() == workers; });
        lock.unlock();  // workers must not wait for the console
        progress(done.load());
        lock.lock();
      }
    } else {
      run_worker(0);
    }
  }  // joins the threads

  const auto first =
      std::min_element(failures.begin(), failures.end(),
                       [](const Failure& a, const Failure& b) { return a.index < b.index; });
  if (first->error) std::rethrow_exception(first->error);
}

}  // namespace rollcontact::batch
