// FFTW3 engine: 2-D transforms as row transforms (r2c/c2r, pruned to the nonzero rows) and
// slow-index column transforms (FFTW_ESTIMATE or FFTW_MEASURE) on the engine's own aligned arrays.
// Compiles to a stub that throws when FFTW is not built.

#include "core/fft_engines.hpp"
#include "rollcontact/errors.hpp"

#if ROLLCONTACT_HAVE_FFTW

#include <fftw3.h>

#include <algorithm>
#include <complex>
#include <cstring>
#include <mutex>
#include <new>
#include <string>
#include <vector>

namespace rollcontact::core::detail {

namespace {

/// The shape of a one-dimensional batch of transforms (FFTW's advanced interface): what decides
/// its plan, apart from the arrays.
struct PlanShape {
  enum class Kind : char { RealToComplex, ComplexToReal, Complex };
  Kind kind = Kind::Complex;
  int n = 0, howmany = 0, istride = 0, idist = 0, ostride = 0, odist = 0, sign = 0;
  bool in_place = false;
  unsigned flags = 0;
  bool operator==(const PlanShape&) const = default;
};

/// FFTW's planner (plan creation and destruction) is not thread-safe and is process-wide, like
/// its wisdom; engines are created per State, possibly on several threads (executing plans is
/// thread-safe). One mutex guards the planner and what this process's planning did.
struct Planner {
  /// Plans shared by all engines of the process, by shape: the engines of one grid (the normal
  /// and tangential operators, their preconditioners) and of grids that share a dimension (the
  /// row transforms of every grid with MX elements, the contact box) each plan a shape once.
  /// Wheel/rail sweeps meet a new grid every few cases, and a plan costs tens of µs even from
  /// wisdom. Engines execute them with the new-array functions on their own fftw_malloc'd
  /// (equally aligned) arrays, in place exactly where the plan is (FFTW manual §4.6; executing
  /// one plan from several threads on different arrays is safe, §5.4). Kept for the process;
  /// beyond kMaxShared shapes engines plan privately.
  static constexpr std::size_t kMaxShared = 4096;
  std::vector<std::pair<PlanShape, fftw_plan>> shared;
  std::mutex mutex;
  /// A plan that no wisdom held was searched for (the plan cache writes wisdom back only then).
  bool learnt = false;
  /// Single-precision wisdom to read before the first single-precision plan, and whether one was
  /// made: reading it at start-up would start FFTW's single-precision planner (≈ 0.4 ms) in
  /// processes that never plan in single precision (small grids).
  std::string pending_single_wisdom;
  bool single_used = false;
};
Planner& planner() {
  // Never destroyed: an engine may be released during static destruction after this would
  // have been, and the shared plans stay reachable to the end (not leaks).
  static Planner& state = *new Planner;
  return state;
}
std::mutex& planner_mutex() {
  return planner().mutex;
}

/// `make(flags)` from wisdom alone first (FFTW_WISDOM_ONLY: a lookup, no search; the plan is
/// the one the planner would make), else by the planner's search. Call under planner_mutex().
template <class Make>
auto plan_wisdom_first(Make make, unsigned flags) {
  if (auto plan = make(flags | FFTW_WISDOM_ONLY)) return plan;
  planner().learnt = true;
  return make(flags);
}

/// A double-precision plan of `shape`, made by make(flags) on the caller's arrays: the shared one,
/// else a new one that becomes shared. `owned` is set when the plan is the caller's to destroy
/// (the shared table is full). Call under planner_mutex().
template <class Make>
fftw_plan shared_plan(const PlanShape& shape, Make make, bool& owned) {
  Planner& state = planner();
  for (const auto& [key, plan] : state.shared)
    if (key == shape) {
      owned = false;
      return plan;
    }
  fftw_plan plan = plan_wisdom_first(make, shape.flags);
  owned = state.shared.size() >= Planner::kMaxShared;
  if (plan != nullptr && !owned) state.shared.emplace_back(shape, plan);
  return plan;
}

class FftwEngine final : public FftEngine {
 public:
  FftwEngine(int n_fast, int n_slow, FftPlanning planning)
      : FftEngine(n_fast, n_slow),
        flags_(planning == FftPlanning::Measure ? FFTW_MEASURE : FFTW_ESTIMATE) {
    real_ = static_cast<double*>(fftw_malloc(sizeof(double) * real_size()));
    spectrum_ = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * spectrum_size()));
    if (real_ == nullptr || spectrum_ == nullptr) {
      release();
      throw std::bad_alloc();
    }
    // Plans are made on first use of a row count: every plan costs planner time.
    std::fill_n(real_, real_size(), 0.0);
  }
  FftwEngine(const FftwEngine&) = delete;
  FftwEngine& operator=(const FftwEngine&) = delete;
  ~FftwEngine() override { release(); }

  void forward(const double* in, std::complex<double>* out) override {
    std::memcpy(real_, in, sizeof(double) * real_size());
    execute_forward(n_slow());
    std::memcpy(static_cast<void*>(out), spectrum_, sizeof(fftw_complex) * spectrum_size());
  }
  void inverse(const std::complex<double>* in, double* out) override {
    // c2r destroys its input: work on the engine's copy.
    std::memcpy(spectrum_, static_cast<const void*>(in), sizeof(fftw_complex) * spectrum_size());
    execute_inverse(n_slow());
    std::memcpy(out, real_, sizeof(double) * real_size());
  }
  std::string_view name() const noexcept override { return "fftw"; }
  double* real_data() noexcept override { return real_; }
  std::complex<double>* spectrum_data() noexcept override {
    // fftw_complex is double[2], layout-compatible with std::complex<double> (FFTW manual §4.1.1).
    return reinterpret_cast<std::complex<double>*>(spectrum_);
  }
  void execute_forward(int rows_in) override {
    rows_in = std::clamp(rows_in, 0, n_slow());
    if (rows_in == 0) {
      std::fill(spectrum_[0], spectrum_[0] + 2 * spectrum_size(), 0.0);
      return;
    }
    // Row-pruned: r2c of the nonzero rows only, zero the other spectrum rows, then the
    // slow-index transforms of all columns. Full transforms (all rows) take the same two steps:
    // FFTW's 2-D plans cost more planner time (≈ 0.5 ms each at 142×162) than they save in
    // the one or two full transforms an engine runs (a kernel's symbol).
    // The slow-index transforms go out of place into columns_ and are transposed back: the
    // convolution's plans serve, and FFTW's in-place strided plans cost 150–300 µs of planner
    // time each (ESTIMATE) for the one or two transforms an engine runs this way (a symbol).
    const Pruned& p = pruned(rows_in);
    ensure_convolution_plans_keeping_arrays();
    fftw_execute_dft_r2c(p.rows_forward, real_, spectrum_);
    std::fill(spectrum_[0] + 2 * half_row_offset(rows_in), spectrum_[0] + 2 * spectrum_size(), 0.0);
    fftw_execute_dft(convolution_forward_, spectrum_, columns_);
    transpose(columns_, n_fast() / 2 + 1, n_slow(), spectrum_);
  }
  void execute_inverse(int rows_out) override {
    rows_out = std::clamp(rows_out, 0, n_slow());
    if (rows_out == 0) return;
    const Pruned& p = pruned(rows_out);
    ensure_convolution_plans_keeping_arrays();
    transpose(spectrum_, n_slow(), n_fast() / 2 + 1, columns_);
    fftw_execute_dft(convolution_inverse_, columns_, spectrum_);
    fftw_execute_dft_c2r(p.rows_inverse, spectrum_, real_);
  }

  // Convolution with the slow-index transforms out of place, into a column-major buffer (where the
  // symbol is applied) and back: FFTW (ESTIMATE) then reads the strided columns once instead of
  // copying them to a buffer and back in place for each direction (the product on the wheel/rail
  // grids got 5–17 % faster).
  void set_convolution_symbol(const std::complex<double>* symbol) override {
    symbol_.resize(spectrum_size());
    to_channel_layout(symbol, symbol_.data());
    ensure_convolution_plans();
  }
  void execute_convolution(int rows_in, int rows_out) override {
    rows_in = std::clamp(rows_in, 0, n_slow());
    rows_out = std::clamp(rows_out, 0, n_slow());
    if (rows_out == 0) return;
    if (rows_in == 0) {
      std::fill_n(real_, static_cast<std::size_t>(n_fast()) * static_cast<std::size_t>(rows_out),
                  0.0);
      return;
    }
    forward_columns(rows_in, columns_);
    multiply(reinterpret_cast<std::complex<double>*>(columns_), symbol_.data(), spectrum_size());
    inverse_columns(columns_, rows_out);
  }

  // Channels in the column-major layout of execute_convolution(): the same out-of-place plans,
  // executed on other (equally aligned, fftw_malloc'd) arrays.
  void set_channel_count(int count) override {
    ensure_convolution_plans();
    free_channels();
    for (int c = 0; c < count; ++c) {
      auto* buffer =
          static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * spectrum_size()));
      if (buffer == nullptr) throw std::bad_alloc();
      channels_fftw_.push_back(buffer);
    }
  }
  std::complex<double>* channel(int c) noexcept override {
    return reinterpret_cast<std::complex<double>*>(channels_fftw_[static_cast<std::size_t>(c)]);
  }
  void forward_to_channel(int rows_in, int c) override {
    rows_in = std::clamp(rows_in, 0, n_slow());
    fftw_complex* out = channels_fftw_[static_cast<std::size_t>(c)];
    if (rows_in == 0) {
      std::fill(out[0], out[0] + 2 * spectrum_size(), 0.0);
      return;
    }
    forward_columns(rows_in, out);
  }
  void inverse_from_channel(int c, int rows_out) override {
    rows_out = std::clamp(rows_out, 0, n_slow());
    if (rows_out == 0) return;
    inverse_columns(channels_fftw_[static_cast<std::size_t>(c)], rows_out);
  }
  void prepare_transforms(int rows_in, int rows_out) override {
    ensure_convolution_plans();
    for (int rows : {rows_in, rows_out}) {
      rows = std::clamp(rows, 0, n_slow());
      if (rows > 0) pruned(rows);
    }
  }
  void to_channel_layout(const std::complex<double>* spectrum,
                         std::complex<double>* out) const override {
    const std::size_t half = static_cast<std::size_t>(n_fast() / 2 + 1);
    const std::size_t ns = static_cast<std::size_t>(n_slow());
    for (std::size_t j = 0; j < ns; ++j) {
      for (std::size_t k = 0; k < half; ++k) out[k * ns + j] = spectrum[j * half + k];
    }
  }

 private:
  /// Keeps real_ and spectrum_ across planning. FFTW_ESTIMATE never touches the arrays (FFTW
  /// manual §4.3.2), so only the other flags pay for copies (at 575×647 two arrays of 12 MB
  /// each, written to fresh pages, for every plan).
  class ArraysKept {
   public:
    explicit ArraysKept(FftwEngine& e) : e_(e) {
      if (e.flags_ == FFTW_ESTIMATE) return;
      real_.assign(e.real_, e.real_ + e.real_size());
      spectrum_.assign(e.spectrum_[0], e.spectrum_[0] + 2 * e.spectrum_size());
    }
    ~ArraysKept() {
      if (e_.flags_ == FFTW_ESTIMATE) return;
      std::copy(real_.begin(), real_.end(), e_.real_);
      std::copy(spectrum_.begin(), spectrum_.end(), e_.spectrum_[0]);
    }
    ArraysKept(const ArraysKept&) = delete;
    ArraysKept& operator=(const ArraysKept&) = delete;

   private:
    FftwEngine& e_;
    std::vector<double> real_, spectrum_;
  };

  /// `in`, `rows` × `cols` row-major, into `out` as `cols` × `rows` row-major (the half-spectrum
  /// between the row-major and the column-major layout), in tiles that stay in cache.
  static void transpose(const fftw_complex* in, int rows, int cols, fftw_complex* out) noexcept {
    constexpr int tile = 16;
    const auto at = [](int i, int j, int width) {
      return static_cast<std::size_t>(i) * static_cast<std::size_t>(width) +
             static_cast<std::size_t>(j);
    };
    for (int i0 = 0; i0 < rows; i0 += tile)
      for (int j0 = 0; j0 < cols; j0 += tile)
        for (int i = i0; i < std::min(i0 + tile, rows); ++i)
          for (int j = j0; j < std::min(j0 + tile, cols); ++j) {
            out[at(j, i, rows)][0] = in[at(i, j, cols)][0];
            out[at(j, i, rows)][1] = in[at(i, j, cols)][1];
          }
  }

  /// ensure_convolution_plans() where real_ and spectrum_ hold data (planning other than
  /// FFTW_ESTIMATE may overwrite them).
  void ensure_convolution_plans_keeping_arrays() {
    if (columns_ != nullptr) return;
    const ArraysKept kept(*this);
    ensure_convolution_plans();
  }

  /// The out-of-place slow-index transforms between spectrum_ and the column-major columns_.
  void ensure_convolution_plans() {
    if (columns_ != nullptr) return;
    columns_ = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * spectrum_size()));
    if (columns_ == nullptr) throw std::bad_alloc();
    const int nf = n_fast(), n = n_slow(), h = nf / 2 + 1;
    {
      std::lock_guard<std::mutex> lock(planner_mutex());
      using Kind = PlanShape::Kind;
      convolution_forward_ =
          planned({Kind::Complex, n, h, h, 1, 1, n, FFTW_FORWARD, false, flags_}, [&](unsigned f) {
            return fftw_plan_many_dft(1, &n, h, spectrum_, nullptr, h, 1, columns_, nullptr, 1, n,
                                      FFTW_FORWARD, f);
          });
      convolution_inverse_ =
          planned({Kind::Complex, n, h, 1, n, h, 1, FFTW_BACKWARD, false, flags_}, [&](unsigned f) {
            return fftw_plan_many_dft(1, &n, h, columns_, nullptr, 1, n, spectrum_, nullptr, h, 1,
                                      FFTW_BACKWARD, f);
          });
    }
    if (convolution_forward_ == nullptr || convolution_inverse_ == nullptr) {
      throw Error("FFTW could not create a convolution plan");
    }
  }

  /// real_data() (rows 0 … rows_in−1, rows_in ≥ 1) → column-major half-spectrum `out`, an array
  /// aligned like columns_ (the convolution plans are executed on it).
  /// The row transforms go to rows_ (not spectrum_, which the inverse transforms overwrite),
  /// whose rows beyond those written stay zero: only rows written before and not now are
  /// cleared, not the zero-padded half of the spectrum at every product (9 % of a wheel/rail
  /// sweep's instructions were that memset). The column plans preserve their input (complex
  /// out of place, FFTW manual §4.3.2).
  void forward_columns(int rows_in, fftw_complex* out) {
    const Pruned& in = pruned(rows_in);
    if (rows_ == nullptr) {
      rows_ = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * spectrum_size()));
      if (rows_ == nullptr) throw std::bad_alloc();
      std::fill(rows_[0], rows_[0] + 2 * spectrum_size(), 0.0);
      rows_written_ = 0;
    }
    fftw_execute_dft_r2c(in.rows_forward, real_, rows_);
    if (rows_written_ > rows_in)
      std::fill(rows_[0] + 2 * half_row_offset(rows_in),
                rows_[0] + 2 * half_row_offset(rows_written_), 0.0);
    rows_written_ = rows_in;
    fftw_execute_dft(convolution_forward_, rows_, out);
  }
  /// Column-major half-spectrum `in` (destroyed) → real_data() rows 0 … rows_out−1 (≥ 1).
  void inverse_columns(fftw_complex* in, int rows_out) {
    // Before the transforms: planning a new row count saves and restores spectrum_ and real_.
    const Pruned& out = pruned(rows_out);
    fftw_execute_dft(convolution_inverse_, in, spectrum_);
    fftw_execute_dft_c2r(out.rows_inverse, spectrum_, real_);
  }

  void free_channels() noexcept {
    for (fftw_complex* buffer : channels_fftw_) fftw_free(buffer);
    channels_fftw_.clear();
  }

  /// Plans of the row-pruned transforms for `rows` rows.
  struct Pruned {
    int rows;
    fftw_plan rows_forward;  // r2c along the fast index of rows 0 … rows−1
    fftw_plan rows_inverse;  // c2r likewise (destroys its input, as allowed)
  };

  std::size_t half_row_offset(int rows) const noexcept {
    return static_cast<std::size_t>(rows) * static_cast<std::size_t>(n_fast() / 2 + 1);
  }

  /// Plans are made on first use of a row count (FftConvolution does this in its constructor,
  /// so its apply() never plans). Planning may overwrite the arrays: ArraysKept keeps them.
  const Pruned& pruned(int rows) {
    for (const Pruned& p : pruned_) {
      if (p.rows == rows) return p;
    }
    const ArraysKept kept(*this);
    const int nf = n_fast(), half = nf / 2 + 1;
    Pruned p{rows, nullptr, nullptr};
    {
      std::lock_guard<std::mutex> lock(planner_mutex());
      using Kind = PlanShape::Kind;
      p.rows_forward = planned({Kind::RealToComplex, nf, rows, 1, nf, 1, half, 0, false, flags_},
                               [&](unsigned f) {
                                 return fftw_plan_many_dft_r2c(1, &nf, rows, real_, nullptr, 1, nf,
                                                               spectrum_, nullptr, 1, half, f);
                               });
      p.rows_inverse = planned({Kind::ComplexToReal, nf, rows, 1, half, 1, nf, 0, false, flags_},
                               [&](unsigned f) {
                                 return fftw_plan_many_dft_c2r(1, &nf, rows, spectrum_, nullptr, 1,
                                                               half, real_, nullptr, 1, nf, f);
                               });
    }
    pruned_.push_back(p);
    if (p.rows_forward == nullptr || p.rows_inverse == nullptr) {
      throw Error("FFTW could not create a pruned plan");
    }
    return pruned_.back();
  }

  /// The plan of `shape` (shared, or the engine's own when the shared table is full; a failed
  /// plan is nullptr). Call under planner_mutex().
  template <class Make>
  fftw_plan planned(const PlanShape& shape, Make make) {
    bool owned = false;
    fftw_plan plan = shared_plan(shape, make, owned);
    if (plan != nullptr && owned) owned_.push_back(plan);
    return plan;
  }

  void release() noexcept {
    {
      std::lock_guard<std::mutex> lock(planner_mutex());
      for (fftw_plan plan : owned_) fftw_destroy_plan(plan);
    }
    owned_.clear();
    pruned_.clear();
    convolution_forward_ = convolution_inverse_ = nullptr;
    if (real_ != nullptr) fftw_free(real_);
    if (spectrum_ != nullptr) fftw_free(spectrum_);
    if (columns_ != nullptr) fftw_free(columns_);
    if (rows_ != nullptr) fftw_free(rows_);
    free_channels();
    real_ = nullptr;
    spectrum_ = nullptr;
    columns_ = nullptr;
    rows_ = nullptr;
  }

  unsigned flags_;  // FFTW_ESTIMATE or FFTW_MEASURE
  double* real_ = nullptr;
  fftw_complex* spectrum_ = nullptr;
  std::vector<Pruned> pruned_;
  fftw_complex* columns_ = nullptr;  // column-major half-spectrum of execute_convolution()
  fftw_complex* rows_ = nullptr;  // row transforms of forward_columns(), zero beyond rows_written_
  int rows_written_ = 0;
  fftw_plan convolution_forward_ = nullptr;   // spectrum_ columns → columns_
  fftw_plan convolution_inverse_ = nullptr;   // columns_ → spectrum_ columns
  std::vector<fftw_complex*> channels_fftw_;  // set_channel_count(), column-major like columns_
  std::vector<fftw_plan> owned_;  // plans not in the shared table (planned()), destroyed here
};

class FftwSingleCirculant final : public SingleCirculant {
 public:
  FftwSingleCirculant(int n_fast, int n_slow, FftPlanning planning)
      : nf_(n_fast),
        ns_(n_slow),
        half_(static_cast<std::size_t>(n_fast / 2 + 1)),
        symbol_(half_ * static_cast<std::size_t>(n_slow), 0.0f) {
    const std::size_t real_size = static_cast<std::size_t>(nf_) * static_cast<std::size_t>(ns_);
    real_ = fftwf_alloc_real(real_size);
    spectrum_ = fftwf_alloc_complex(symbol_.size());
    if (real_ == nullptr || spectrum_ == nullptr) {
      release();
      throw std::bad_alloc();
    }
    flags_ = planning == FftPlanning::Measure ? FFTW_MEASURE : FFTW_ESTIMATE;
    const int half = static_cast<int>(half_);
    {
      // The slow-index transforms of all columns, in place; the row transforms follow on first
      // use, pruned to the block's rows.
      std::lock_guard<std::mutex> lock(planner_mutex());
      Planner& state = planner();
      if (!state.pending_single_wisdom.empty())
        fftwf_import_wisdom_from_string(state.pending_single_wisdom.c_str());
      state.pending_single_wisdom.clear();
      state.single_used = true;
      const auto columns = [&](int sign) {
        return plan_wisdom_first(
            [&](unsigned f) {
              return fftwf_plan_many_dft(1, &ns_, half, spectrum_, nullptr, half, 1, spectrum_,
                                         nullptr, half, 1, sign, f);
            },
            flags_);
      };
      columns_forward_ = columns(FFTW_FORWARD);
      columns_inverse_ = columns(FFTW_BACKWARD);
    }
    if (columns_forward_ == nullptr || columns_inverse_ == nullptr) {
      release();
      throw Error("FFTW could not create a single-precision plan");
    }
  }
  FftwSingleCirculant(const FftwSingleCirculant&) = delete;
  FftwSingleCirculant& operator=(const FftwSingleCirculant&) = delete;
  ~FftwSingleCirculant() override { release(); }

  void set_symbol(const double* symbol) override {
    for (std::size_t k = 0; k < symbol_.size(); ++k) symbol_[k] = static_cast<float>(symbol[k]);
  }

  double apply_dot(const double* in, double* out, int mx, int my) override {
    const std::size_t nf = static_cast<std::size_t>(nf_), m = static_cast<std::size_t>(mx);
    plan_rows(my);
    for (int iy = 0; iy < my; ++iy) {
      float* dst = real_ + nf * static_cast<std::size_t>(iy);
      const double* src = in + m * static_cast<std::size_t>(iy);
      for (std::size_t ix = 0; ix < m; ++ix) dst[ix] = static_cast<float>(src[ix]);
      std::fill(dst + m, dst + nf, 0.0f);
    }
    // Rows 0 … my−1 hold the block, the others are zero: r2c of the block's rows only, then
    // the columns; back likewise, to the block's rows only.
    fftwf_execute(rows_forward_);
    float* s = spectrum_[0];
    std::fill(s + 2 * half_ * static_cast<std::size_t>(my), s + 2 * symbol_.size(), 0.0f);
    fftwf_execute(columns_forward_);
    for (std::size_t k = 0; k < symbol_.size(); ++k) {
      s[2 * k] *= symbol_[k];
      s[2 * k + 1] *= symbol_[k];
    }
    fftwf_execute(columns_inverse_);
    fftwf_execute(rows_inverse_);
    double dot[4] = {0.0, 0.0, 0.0, 0.0};  // independent sums (addition latency)
    for (int iy = 0; iy < my; ++iy) {
      const float* src = real_ + nf * static_cast<std::size_t>(iy);
      const double* r = in + m * static_cast<std::size_t>(iy);
      double* z = out + m * static_cast<std::size_t>(iy);
      std::size_t ix = 0;
      for (; ix + 4 <= m; ix += 4)
        for (std::size_t l = 0; l < 4; ++l) {
          z[ix + l] = static_cast<double>(src[ix + l]);
          dot[l] += r[ix + l] * z[ix + l];
        }
      for (; ix < m; ++ix) {
        z[ix] = static_cast<double>(src[ix]);
        dot[0] += r[ix] * z[ix];
      }
    }
    return (dot[0] + dot[1]) + (dot[2] + dot[3]);
  }

 private:
  /// The row transforms for `rows` rows (planned again only if the block's height changes).
  /// Planning may overwrite the arrays (FFTW_MEASURE); apply_dot() fills them afterwards.
  void plan_rows(int rows) {
    if (rows == planned_rows_) return;
    destroy_row_plans();
    const int half = static_cast<int>(half_);
    {
      std::lock_guard<std::mutex> lock(planner_mutex());
      rows_forward_ = plan_wisdom_first(
          [&](unsigned f) {
            return fftwf_plan_many_dft_r2c(1, &nf_, rows, real_, nullptr, 1, nf_, spectrum_,
                                           nullptr, 1, half, f);
          },
          flags_);
      rows_inverse_ = plan_wisdom_first(
          [&](unsigned f) {
            return fftwf_plan_many_dft_c2r(1, &nf_, rows, spectrum_, nullptr, 1, half, real_,
                                           nullptr, 1, nf_, f);
          },
          flags_);
    }
    if (rows_forward_ == nullptr || rows_inverse_ == nullptr) {
      destroy_row_plans();
      throw Error("FFTW could not create a single-precision plan");
    }
    planned_rows_ = rows;
  }
  void destroy_row_plans() noexcept {
    std::lock_guard<std::mutex> lock(planner_mutex());
    if (rows_forward_ != nullptr) fftwf_destroy_plan(rows_forward_);
    if (rows_inverse_ != nullptr) fftwf_destroy_plan(rows_inverse_);
    rows_forward_ = rows_inverse_ = nullptr;
    planned_rows_ = -1;
  }

  void release() noexcept {
    destroy_row_plans();
    {
      std::lock_guard<std::mutex> lock(planner_mutex());
      if (columns_forward_ != nullptr) fftwf_destroy_plan(columns_forward_);
      if (columns_inverse_ != nullptr) fftwf_destroy_plan(columns_inverse_);
    }
    columns_forward_ = columns_inverse_ = nullptr;
    if (real_ != nullptr) fftwf_free(real_);
    if (spectrum_ != nullptr) fftwf_free(spectrum_);
    real_ = nullptr;
    spectrum_ = nullptr;
  }

  int nf_, ns_;
  std::size_t half_;
  std::vector<float> symbol_;  // real symbol per half-spectrum entry
  float* real_ = nullptr;
  fftwf_complex* spectrum_ = nullptr;
  unsigned flags_ = FFTW_ESTIMATE;
  fftwf_plan columns_forward_ = nullptr;  // slow-index transforms of all columns, in place
  fftwf_plan columns_inverse_ = nullptr;
  int planned_rows_ = -1;              // rows of rows_forward_ and rows_inverse_
  fftwf_plan rows_forward_ = nullptr;  // r2c of the block's rows
  fftwf_plan rows_inverse_ = nullptr;  // c2r back to them (destroys the spectrum)
};

}  // namespace

std::unique_ptr<FftEngine> make_fftw_engine(int n_fast, int n_slow, FftPlanning planning) {
  return std::make_unique<FftwEngine>(n_fast, n_slow, planning);
}

bool fftw_planned_beyond_wisdom() noexcept {
  std::lock_guard<std::mutex> lock(planner_mutex());
  return planner().learnt;
}

void defer_single_precision_wisdom(std::string text) {
  std::lock_guard<std::mutex> lock(planner_mutex());
  planner().pending_single_wisdom = std::move(text);
}

bool fftw_single_precision_used() noexcept {
  std::lock_guard<std::mutex> lock(planner_mutex());
  return planner().single_used;
}

std::unique_ptr<SingleCirculant> make_fftw_single_circulant(int n_fast, int n_slow,
                                                            FftPlanning planning) {
  return std::make_unique<FftwSingleCirculant>(n_fast, n_slow, planning);
}

}  // namespace rollcontact::core::detail

#else

namespace rollcontact::core::detail {

std::unique_ptr<FftEngine> make_fftw_engine(int /*n_fast*/, int /*n_slow*/,
                                            FftPlanning /*planning*/) {
  throw NotSupportedError("the FFTW backend was not built");
}

std::unique_ptr<SingleCirculant> make_fftw_single_circulant(int /*n_fast*/, int /*n_slow*/,
                                                            FftPlanning /*planning*/) {
  return nullptr;
}

bool fftw_planned_beyond_wisdom() noexcept {
  return false;
}

void defer_single_precision_wisdom(std::string /*text*/) {}

bool fftw_single_precision_used() noexcept {
  return false;
}

}  // namespace rollcontact::core::detail

#endif
