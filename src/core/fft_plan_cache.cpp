#include "rollcontact/fft_plan_cache.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#include "core/fft_engines.hpp"

#if ROLLCONTACT_HAVE_FFTW
#include <fftw3.h>
#endif

namespace rollcontact {

namespace {

constexpr const char* double_file = "fftw-wisdom-double.txt";
constexpr const char* single_file = "fftw-wisdom-float.txt";

/// Reading wisdom costs about 0.2 ms plus 12 µs per kB (FFTW 3.3.10 here): a file that has
/// grown beyond this (a process that planned many sizes, e.g. `validate`) is not read, so the
/// process plans afresh and the file is replaced by its own, smaller wisdom. 32 kB hold the
/// plans of about five grid sizes.
constexpr std::uintmax_t max_wisdom_bytes = 32 * 1024;

std::string read_text(const std::filesystem::path& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > max_wisdom_bytes) return {};
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Replaces `path` atomically (a temporary next to it, then rename): processes running at the
/// same time each leave a complete file, never a mixture.
void write_text_atomically(const std::filesystem::path& path, const std::string& text) {
  std::error_code ec;
  std::filesystem::create_directories(path.parent_path(), ec);
  if (ec) return;
  std::filesystem::path tmp = path;
  tmp += ".tmp" + std::to_string(static_cast<long>(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return;
    out << text;
    if (!out.flush()) {
      out.close();
      std::filesystem::remove(tmp, ec);
      return;
    }
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) std::filesystem::remove(tmp, ec);
}

/// The entries of a wisdom text in sorted order: FFTW exports its hash table in an order that
/// varies from process to process, so the text alone would look changed after every run.
std::vector<std::string> sorted_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::sort(lines.begin(), lines.end());
  return lines;
}

/// Writes `now` to `path` unless it holds the same entries as `before` (what the file held) or
/// is too long to be read again: a process that planned many sizes (a wheel/rail sweep meets a
/// new grid every few cases) would otherwise leave a file that no later process reads, and the
/// small runs that the file served would plan afresh.
void write_if_changed(const std::filesystem::path& path, const std::string& now,
                      const std::string& before) {
  if (now.empty() || now.size() > max_wisdom_bytes) return;
  if (sorted_lines(now) == sorted_lines(before)) return;
  write_text_atomically(path, now);
}

#if ROLLCONTACT_HAVE_FFTW
/// FFTW's wisdom as text (its own allocation, released with fftw_free).
template <class Export, class Free>
std::string exported(Export export_to_string, Free free_string) {
  char* s = export_to_string();
  if (s == nullptr) return {};
  std::string text(s);
  free_string(s);
  return text;
}
#endif

}  // namespace

std::optional<std::filesystem::path> default_fft_plan_cache_dir() {
  if (const char* dir = std::getenv("ROLLCONTACT_CACHE_DIR")) {
    if (*dir == '\0') return std::nullopt;
    return std::filesystem::path(dir);
  }
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0')
    return std::filesystem::path(xdg) / "rollcontact";
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
    return std::filesystem::path(home) / ".cache" / "rollcontact";
  return std::nullopt;
}

FftPlanCache::FftPlanCache(std::filesystem::path dir) : dir_(std::move(dir)) {
#if ROLLCONTACT_HAVE_FFTW
  double_text_ = read_text(dir_ / double_file);
  single_text_ = read_text(dir_ / single_file);
  // An import that fails (another FFTW version or configuration) changes nothing. The
  // single-precision wisdom is read only before a single-precision plan is made.
  const bool d = !double_text_.empty() && fftw_import_wisdom_from_string(double_text_.c_str());
  core::detail::defer_single_precision_wisdom(single_text_);
  imported_ = d;
#endif
}

FftPlanCache::~FftPlanCache() {
#if ROLLCONTACT_HAVE_FFTW
  if (!core::detail::fftw_planned_beyond_wisdom()) return;  // nothing the files lack
  try {
    const std::string d = exported(fftw_export_wisdom_to_string, [](char* s) { fftw_free(s); });
    write_if_changed(dir_ / double_file, d, double_text_);
    if (core::detail::fftw_single_precision_used()) {
      const std::string f = exported(fftwf_export_wisdom_to_string, [](char* s) { fftwf_free(s); });
      write_if_changed(dir_ / single_file, f, single_text_);
    }
  } catch (...) {  // a cache: never fail the run for it
  }
#endif
}

}  // namespace rollcontact
