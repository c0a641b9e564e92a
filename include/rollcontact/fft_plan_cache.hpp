#pragma once
// FFTW's plans kept between processes ("wisdom", FFTW manual §4.7).
//
// A process that plans a transform size for the first time pays the planner's search: at the
// sizes of a 71×81 grid about 3 ms for the plans of one normal problem, more than the solve.
// FFTW records what it chose and can read it back, after which planning the same sizes takes
// microseconds. Only FFTW_ESTIMATE wisdom is kept: ESTIMATE plans depend on nothing but the
// sizes and the FFTW build, so a plan read back is the plan the planner would have made, and
// results stay bit for bit those of a process without the file. (MEASURE plans depend on
// timings; a process that measures neither reads nor writes the file.)

#include <filesystem>
#include <optional>
#include <string>

namespace rollcontact {

/// Where a process keeps FFTW's wisdom: $ROLLCONTACT_CACHE_DIR if set (empty: nowhere), else
/// $XDG_CACHE_HOME/rollcontact, else $HOME/.cache/rollcontact; nullopt without any of them.
std::optional<std::filesystem::path> default_fft_plan_cache_dir();

/// Reads the wisdom files in `dir` (double and single precision) on construction and, on
/// destruction, writes them back when this process planned something new. Files that are
/// missing, unreadable, from another FFTW build or larger than 32 kB (reading costs time too)
/// are ignored and replaced; a directory that cannot be written is left alone. Construct it before
/// the first plan and destroy it after the last, on one thread (FFTW's planner is not thread-safe).
class FftPlanCache {
 public:
  explicit FftPlanCache(std::filesystem::path dir);
  ~FftPlanCache();
  FftPlanCache(const FftPlanCache&) = delete;
  FftPlanCache& operator=(const FftPlanCache&) = delete;

  /// Whether the double-precision file held wisdom of this FFTW build (the single-precision one
  /// is read only before the process's first single-precision plan).
  bool imported() const noexcept { return imported_; }

 private:
  std::filesystem::path dir_;
  std::string double_text_, single_text_;  ///< as read: written back only when changed
  bool imported_ = false;
};

}  // namespace rollcontact
