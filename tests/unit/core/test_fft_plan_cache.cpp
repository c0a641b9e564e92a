// FFTW's wisdom kept between processes (rollcontact/fft_plan_cache.hpp): where it is kept, that it
// is written and read back, and that plans read back transform bit for bit as planned ones.

#include <gtest/gtest.h>

#include <complex>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "core/fft_backend.hpp"
#include "rollcontact/fft_plan_cache.hpp"
#include "support/files.hpp"
#include "support/random_field.hpp"

#if ROLLCONTACT_HAVE_FFTW
#include <fftw3.h>
#endif

namespace rollcontact {
namespace {

/// Sets an environment variable for the scope (nullptr: unset) and restores it.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      ::setenv(name, value, 1);
    else
      ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(FftWisdomDir, FromTheEnvironment) {
  {
    const ScopedEnv a("ROLLCONTACT_CACHE_DIR", "/some/where");
    EXPECT_EQ(default_fft_plan_cache_dir(), std::filesystem::path("/some/where"));
  }
  {
    const ScopedEnv a("ROLLCONTACT_CACHE_DIR", "");  // switched off
    EXPECT_FALSE(default_fft_plan_cache_dir());
  }
  const ScopedEnv a("ROLLCONTACT_CACHE_DIR", nullptr);
  {
    const ScopedEnv b("XDG_CACHE_HOME", "/xdg");
    EXPECT_EQ(default_fft_plan_cache_dir(), std::filesystem::path("/xdg/rollcontact"));
  }
  const ScopedEnv b("XDG_CACHE_HOME", nullptr);
  const ScopedEnv c("HOME", "/home/u");
  EXPECT_EQ(default_fft_plan_cache_dir(), std::filesystem::path("/home/u/.cache/rollcontact"));
}

#if ROLLCONTACT_HAVE_FFTW
std::vector<std::complex<double>> spectrum_of(const std::vector<double>& x, int nf, int ns) {
  auto engine = core::make_fft_engine(FftBackendKind::Fftw, nf, ns);
  std::vector<std::complex<double>> out(engine->spectrum_size());
  engine->forward(x.data(), out.data());
  return out;
}

TEST(FftPlanCache, WrittenAndReadBackWithTheSameTransforms) {
  // A folder that does not exist yet: the cache makes it.
  const test_support::ScratchDir scratch("wisdom-test");
  const std::filesystem::path dir = scratch / "wisdom";
  // A size no other test plans (210 = 2·3·5·7, 54 = 2·3³), so that this process must plan it.
  const int nf = 210, ns = 54;
  const std::vector<double> x = test_support::random_field(static_cast<std::size_t>(nf * ns), 7);
  std::vector<std::complex<double>> planned;
  {
    const FftPlanCache wisdom(dir);
    EXPECT_FALSE(wisdom.imported());
    planned = spectrum_of(x, nf, ns);
  }
  ASSERT_TRUE(std::filesystem::exists(dir / "fftw-wisdom-double.txt"));
  std::ifstream in(dir / "fftw-wisdom-double.txt");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("fftw_wisdom"), std::string::npos);
  EXPECT_NE(text.find("fftw_codelet"), std::string::npos);  // plans, not just the header

  fftw_forget_wisdom();  // as a new process would start
  {
    const FftPlanCache wisdom(dir);
    EXPECT_TRUE(wisdom.imported());
    const std::vector<std::complex<double>> again = spectrum_of(x, nf, ns);
    ASSERT_EQ(again.size(), planned.size());
    for (std::size_t k = 0; k < planned.size(); ++k) {
      EXPECT_EQ(again[k].real(), planned[k].real()) << k;  // bit for bit
      EXPECT_EQ(again[k].imag(), planned[k].imag()) << k;
    }
  }
}

TEST(FftPlanCache, LargeFilesAreNotReadButReplaced) {
  const test_support::ScratchDir scratch("wisdom-large");
  const std::filesystem::path& dir = scratch.path();
  fftw_forget_wisdom();  // this process's own wisdom stays short enough to be written
  // Valid wisdom padded beyond 32 kB with blank lines (which FFTW's reader skips).
  char* header = fftw_export_wisdom_to_string();
  const std::string large = std::string(header) + std::string(40 * 1024, '\n');
  fftw_free(header);
  std::ofstream(dir / "fftw-wisdom-double.txt") << large;
  {
    const FftPlanCache wisdom(dir);
    EXPECT_FALSE(wisdom.imported());
    spectrum_of(test_support::random_field(30 * 14, 3), 30, 14);
  }
  EXPECT_LT(std::filesystem::file_size(dir / "fftw-wisdom-double.txt"), large.size());
}

TEST(FftPlanCache, WisdomTooLongToReadAgainIsNotWritten) {
  const test_support::ScratchDir scratch("wisdom-long");
  const std::filesystem::path& dir = scratch.path();
  fftw_forget_wisdom();
  // A file a small run left: one size's plans.
  {
    const FftPlanCache wisdom(dir);
    spectrum_of(test_support::random_field(30 * 14, 3), 30, 14);
  }
  std::ifstream in(dir / "fftw-wisdom-double.txt");
  const std::string small((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_NE(small.find("fftw_codelet"), std::string::npos);
  fftw_forget_wisdom();
  {
    // A run that plans many sizes (as a wheel/rail sweep meets a new grid every few cases).
    const FftPlanCache wisdom(dir);
    EXPECT_TRUE(wisdom.imported());
    for (int nf = 18; nf <= 130; nf += 4)
      spectrum_of(test_support::random_field(static_cast<std::size_t>(nf) * 22, 5), nf, 22);
    char* text = fftw_export_wisdom_to_string();
    EXPECT_GT(std::string(text).size(), 32u * 1024u);  // too long to be read again
    fftw_free(text);
  }
  std::ifstream again(dir / "fftw-wisdom-double.txt");
  const std::string kept((std::istreambuf_iterator<char>(again)), std::istreambuf_iterator<char>());
  EXPECT_EQ(kept, small);  // the small run's file still serves small runs
}

TEST(FftPlanCache, UnusableFilesAreIgnored) {
  const test_support::ScratchDir scratch("wisdom-bad");
  const std::filesystem::path& dir = scratch.path();
  std::ofstream(dir / "fftw-wisdom-double.txt") << "(fftw-0.0 not wisdom at all";
  std::ofstream(dir / "fftw-wisdom-float.txt") << "";
  const FftPlanCache wisdom(dir);
  EXPECT_FALSE(wisdom.imported());
}
#endif

}  // namespace
}  // namespace rollcontact
