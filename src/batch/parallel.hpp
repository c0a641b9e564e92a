#pragma once
// One parallel loop for the batch jobs (creep table, validation, later parameter sweeps): a
// fixed number of worker threads over the indices 0 … n−1, each worker with an index of its
// own so that it can keep per-thread state (a PatchSolver with its operator cache).

#include <cstddef>
#include <functional>

namespace rollcontact::batch {

enum class Schedule {
  /// Index i on worker i mod workers, in increasing order: a worker sees every workers-th case,
  /// so runs of cases that share a grid keep one cached operator per worker.
  Cyclic,
  /// The next free index to whichever worker is free: for jobs of very different length.
  Dynamic,
};

struct ParallelOptions {
  int threads = 1;  ///< workers; < 1 counts as 1, more than n is cut to n
  Schedule schedule = Schedule::Dynamic;
};

/// Worker threads for a request: `requested` when positive, else the machine's hardware threads
/// (at least 1).
int default_thread_count(int requested);

/// The workers parallel_for uses for n indices: `threads` clamped to [1, n] (1 for n = 0), so that
/// callers can size their per-worker state.
std::size_t worker_count(std::size_t n, int threads);

/// Runs body(worker, index) for every index in [0, n). With one worker and no progress
/// callback everything runs on the calling thread. `progress(done)`, when given, is called on
/// the calling thread about every 0.2 s and once at the end with the number of indices
/// finished, while the workers run; the workers never wait for it.
///
/// A worker that throws stops; the others finish their indices. Afterwards the exception of
/// the lowest index is rethrown (deterministic whatever the timing). With a progress callback
/// even one worker runs on a thread of its own, so that the caller can report.
void parallel_for(std::size_t n, const ParallelOptions& options,
                  const std::function<void(std::size_t worker, std::size_t index)>& body,
                  const std::function<void(std::size_t done)>& progress = {});

}  // namespace rollcontact::batch
