#include "views/axis_ticks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace crux {

Ticks nice_ticks(double min, double max, int target) {
  if (!std::isfinite(min) || !std::isfinite(max)) {
    throw std::invalid_argument(fmt::format("nice_ticks: the range [{}, {}] is not finite", min, max));
  }
  if (min > max) std::swap(min, max);
  if (max - min <= 1e-12 * std::max(1.0, std::abs(max))) {
    const double pad = min == 0 ? 1.0 : 0.1 * std::abs(min);
    min -= pad;
    max += pad;
  }
  target = std::max(1, target);
  const double raw = (max - min) / target;
  double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  constexpr std::array<double, 3> kMultiples{1, 2, 5};
  Ticks ticks;
  for (int attempt = 0;; ++attempt) {
    const double step = kMultiples[attempt % 3] * magnitude;
    // The tolerance keeps a bound that is a multiple of the step from adding a tick.
    const double low = std::floor(min / step + 1e-9), high = std::ceil(max / step - 1e-9);
    if (high - low <= target) {
      ticks.step = step;
      for (double k = low; k <= high; k += 1) ticks.values.push_back(k * step);
      break;
    }
    if (attempt % 3 == 2) magnitude *= 10;
  }
  ticks.low = ticks.values.front();
  ticks.high = ticks.values.back();
  return ticks;
}

std::string tick_label(double value, double step, double magnitude) {
  if (std::abs(value) < 1e-6 * std::abs(step)) return "0";
  int exponent = 0;
  if (magnitude >= 1e5) exponent = std::min(9, 3 * static_cast<int>(std::floor(std::log10(magnitude) / 3 + 1e-9)));
  static constexpr std::array<const char*, 4> kSuffixes{"", "k", "M", "G"};
  const double divisor = std::pow(10.0, exponent);
  const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(std::abs(step) / divisor) - 1e-9)));
  return fmt::format("{:.{}f}{}", value / divisor, decimals, kSuffixes[exponent / 3]);
}

double metre_tick_spacing(double pixels_per_metre) {
  constexpr double kFinestSpacing = 0.5;  // metres
  constexpr double kMinimumGap = 30;      // pixels
  double spacing = kFinestSpacing;
  while (spacing * pixels_per_metre < kMinimumGap) spacing *= 2;
  return spacing;
}

std::vector<double> metre_ticks(double low, double high, double spacing) {
  std::vector<double> values;
  const auto last = static_cast<long>(std::floor(high / spacing));
  for (auto k = static_cast<long>(std::ceil(low / spacing)); k <= last; ++k) {
    values.push_back(static_cast<double>(k) * spacing);
  }
  return values;
}

std::string metre_tick_label(double metres) { return fmt::format("{:.1f}", metres + 0.0); }

}  // namespace crux
