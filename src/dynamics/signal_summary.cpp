#include <algorithm>
#include <cmath>
#include <numbers>

#include "rollcontact/dynamics.hpp"

namespace rollcontact::dynamics {

SignalSummary summarise_force(const std::vector<TimeSample>& history, double window_s,
                              double max_frequency_Hz) {
  SignalSummary out;
  if (history.empty()) return out;
  const double t_end = history.back().t_s;
  std::vector<double> t, f;
  for (const TimeSample& s : history)
    if (s.t_s >= t_end - window_s) {
      t.push_back(s.t_s);
      f.push_back(s.fz_N);
    }
  out.samples = static_cast<int>(f.size());
  if (f.empty()) return out;
  double sum = 0.0;
  for (double v : f) sum += v;
  out.mean = sum / static_cast<double>(f.size());
  const auto [lo, hi] = std::minmax_element(f.begin(), f.end());
  out.min = *lo;
  out.max = *hi;
  if (f.size() < 8) return out;
  // Hann-windowed DFT of the mean-free force on a 0.5 Hz grid up to the Nyquist frequency (or
  // max_frequency_Hz):
  // finer than the window's 1/T resolution, so that the peak's place is not rounded to it.
  const double span = t.back() - t.front();
  const double nyquist = std::min(max_frequency_Hz, 0.5 * static_cast<double>(f.size() - 1) / span);
  const double two_pi = 2.0 * std::numbers::pi;
  double best = 0.0;
  for (double freq = 2.0 / span; freq < nyquist; freq += 0.5) {
    double re = 0.0, im = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const double hann = 0.5 * (1.0 - std::cos(two_pi * (t[i] - t.front()) / span));
      const double v = hann * (f[i] - out.mean);
      re += v * std::cos(two_pi * freq * t[i]);
      im += v * std::sin(two_pi * freq * t[i]);
    }
    const double amp = re * re + im * im;
    if (amp > best) {
      best = amp;
      out.dominant_frequency_Hz = freq;
    }
  }
  return out;
}

}  // namespace rollcontact::dynamics
