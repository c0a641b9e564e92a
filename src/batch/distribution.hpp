#pragma once
// The processes of one run: one, or the ranks of an MPI job (the CLI provides that one, so that
// the library itself does not depend on MPI). Batch jobs whose cases are independent (the
// creep-force table, parameter sweeps) hand their cases out through map_gather(): whichever
// process is free takes the next chunk (cases differ in cost by 100×), and the root receives
// every result in case order, so that the files it writes do not depend on the process count.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace rollcontact::batch {

class Distribution {
 public:
  virtual ~Distribution() = default;

  [[nodiscard]] virtual int rank() const = 0;  ///< 0 … size()−1; 0 is the root
  [[nodiscard]] virtual int size() const = 0;  ///< number of processes
  [[nodiscard]] bool is_root() const { return rank() == 0; }

  /// Runs body(i) for every i in [0, n) once, on some process, the indices handed out in
  /// chunks of `chunk` consecutive ones (neighbouring cases tend to share operators) to
  /// whichever process asks first. Returns body's results in index order on the root and an
  /// empty vector elsewhere. Collective: every process calls it with the same n and chunk.
  /// A body that throws on any process makes every process throw afterwards.
  virtual std::vector<std::string> map_gather(
      std::size_t n, std::size_t chunk, const std::function<std::string(std::size_t)>& body) = 0;

  /// The largest `value` over all processes, on every process (collective).
  virtual int max_over_processes(int value) = 0;
};

/// One process: map_gather is a plain loop.
class SerialDistribution final : public Distribution {
 public:
  [[nodiscard]] int rank() const override { return 0; }
  [[nodiscard]] int size() const override { return 1; }
  std::vector<std::string> map_gather(std::size_t n, std::size_t chunk,
                                      const std::function<std::string(std::size_t)>& body) override;
  int max_over_processes(int value) override { return value; }
};

/// A chunk size for n cases over `processes`: about 16 chunks per process, at least 1.
std::size_t default_chunk(std::size_t n, int processes);

}  // namespace rollcontact::batch
