// The MPI process distribution, a plugin of the command-line program: `rollcontact` loads it
// (dlopen) only when launched by mpirun, so that a plain run does not load and initialise Open
// MPI's libraries (≈ 1.3 ms of every process on the benchmark machine, issue 16).

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "batch/distribution.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::cli {

namespace {

/// MPI_COMM_WORLD. Work is handed out through a counter on the root that every rank advances
/// with an atomic fetch-and-add (one-sided, passive target), so no rank has to serve requests
/// and the root computes like the others; the results are gathered once at the end.
class MpiDistribution final : public batch::Distribution {
 public:
  MpiDistribution(int& argc, char**& argv) {
    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiDistribution() override { MPI_Finalize(); }
  MpiDistribution(const MpiDistribution&) = delete;
  MpiDistribution& operator=(const MpiDistribution&) = delete;

  [[nodiscard]] int rank() const override { return rank_; }
  [[nodiscard]] int size() const override { return size_; }

  std::vector<std::string> map_gather(
      std::size_t n, std::size_t chunk,
      const std::function<std::string(std::size_t)>& body) override {
    std::vector<std::pair<std::uint64_t, std::string>> mine;
    std::string failure;
    compute_share(n, chunk == 0 ? 1 : chunk, body, mine, failure);
    const int failed = max_over_processes(failure.empty() ? 0 : 1);
    if (failed != 0)
      throw Error(failure.empty() ? "a case failed on another MPI process" : failure);
    return gather(n, mine);
  }

  int max_over_processes(int value) override {
    int out = value;
    MPI_Allreduce(&value, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return out;
  }

 private:
  void compute_share(std::size_t n, std::size_t chunk,
                     const std::function<std::string(std::size_t)>& body,
                     std::vector<std::pair<std::uint64_t, std::string>>& mine,
                     std::string& failure) const {
    std::uint64_t* counter = nullptr;
    MPI_Win win = MPI_WIN_NULL;
    const MPI_Aint bytes = rank_ == 0 ? static_cast<MPI_Aint>(sizeof(std::uint64_t)) : 0;
    MPI_Win_allocate(bytes, sizeof(std::uint64_t), MPI_INFO_NULL, MPI_COMM_WORLD, &counter, &win);
    if (rank_ == 0) {
      MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, win);
      *counter = 0;
      MPI_Win_unlock(0, win);
    }
    MPI_Barrier(MPI_COMM_WORLD);
    MPI_Win_lock_all(0, win);
    const std::uint64_t step = chunk;
    for (;;) {
      std::uint64_t start = 0;
      MPI_Fetch_and_op(&step, &start, MPI_UINT64_T, 0, 0, MPI_SUM, win);
      MPI_Win_flush(0, win);
      if (start >= n) break;
      const std::uint64_t end = std::min<std::uint64_t>(n, start + step);
      for (std::uint64_t i = start; i < end; ++i) {
        if (!failure.empty()) continue;  // keep taking chunks so that the others finish
        try {
          mine.emplace_back(i, body(static_cast<std::size_t>(i)));
        } catch (const std::exception& e) {
          failure = e.what();
        }
      }
    }
    MPI_Win_unlock_all(win);
    MPI_Win_free(&win);
  }

  /// Packs (index, length, bytes) records, gathers them on the root and puts them in order.
  std::vector<std::string> gather(
      std::size_t n, const std::vector<std::pair<std::uint64_t, std::string>>& mine) const {
    std::string packed;
    for (const auto& [index, bytes] : mine) {
      const std::uint64_t header[2] = {index, bytes.size()};
      packed.append(reinterpret_cast<const char*>(header), sizeof header);
      packed.append(bytes);
    }
    if (packed.size() > static_cast<std::size_t>(INT32_MAX))
      throw Error("more than 2 GB of results on one MPI process");
    const int length = static_cast<int>(packed.size());
    std::vector<int> lengths(static_cast<std::size_t>(size_)), offsets(lengths.size());
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::string all;
    if (rank_ == 0) {
      std::size_t total = 0;
      for (std::size_t r = 0; r < lengths.size(); ++r) {
        offsets[r] = static_cast<int>(total);
        total += static_cast<std::size_t>(lengths[r]);
      }
      if (total > static_cast<std::size_t>(INT32_MAX))
        throw Error("more than 2 GB of results to gather on the root");
      all.resize(total);
    }
    MPI_Gatherv(packed.data(), length, MPI_BYTE, all.data(), lengths.data(), offsets.data(),
                MPI_BYTE, 0, MPI_COMM_WORLD);
    std::vector<std::string> out;
    if (rank_ != 0) return out;
    out.resize(n);
    std::vector<char> seen(n, 0);
    for (std::size_t pos = 0; pos < all.size();) {
      std::uint64_t header[2];
      std::memcpy(header, all.data() + pos, sizeof header);
      pos += sizeof header;
      out[header[0]] = all.substr(pos, header[1]);
      seen[header[0]] = 1;
      pos += header[1];
    }
    for (std::size_t i = 0; i < n; ++i)
      if (!seen[i]) throw Error("case " + std::to_string(i + 1) + " was computed by no process");
    return out;
  }

  int rank_ = 0, size_ = 1;
};

}  // namespace

}  // namespace rollcontact::cli

/// The entry point process_distribution.cpp looks up: MPI_Init and the distribution over
/// MPI_COMM_WORLD (deleted by the caller, which finalises MPI).
extern "C" __attribute__((visibility("default"))) rollcontact::batch::Distribution*
rollcontact_mpi_distribution(int* argc, char*** argv) {
  return new rollcontact::cli::MpiDistribution(*argc, *argv);
}
