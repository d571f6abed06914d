#include "experiments/statistics.hpp"

#include <cassert>
#include <cmath>
#include <limits>

namespace crux {

namespace {

// Continued fraction of the regularised incomplete beta function (modified Lentz).
double beta_continued_fraction(double a, double b, double x) {
  constexpr double tiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  d = 1.0 / (std::abs(d) < tiny ? tiny : d);
  double result = d;
  for (int m = 1; m <= 300; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((a + m2 - 1.0) * (a + m2));
    d = 1.0 + aa * d;
    c = 1.0 + aa / c;
    d = 1.0 / (std::abs(d) < tiny ? tiny : d);
    c = std::abs(c) < tiny ? tiny : c;
    result *= d * c;
    aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0));
    d = 1.0 + aa * d;
    c = 1.0 + aa / c;
    d = 1.0 / (std::abs(d) < tiny ? tiny : d);
    c = std::abs(c) < tiny ? tiny : c;
    const double delta = d * c;
    result *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return result;
}

double regularized_incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double front =
      std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1.0) / (a + b + 2.0)) return front * beta_continued_fraction(a, b, x) / a;
  return 1.0 - front * beta_continued_fraction(b, a, 1.0 - x) / b;
}

}  // namespace

double student_t_cdf(double t, double dof) {
  const double tail = 0.5 * regularized_incomplete_beta(dof / 2.0, 0.5, dof / (dof + t * t));
  return t >= 0 ? 1.0 - tail : tail;
}

double student_t_quantile(double probability, double dof) {
  assert(probability > 0.0 && probability < 1.0);
  double low = -1e3, high = 1e3;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (low + high);
    (student_t_cdf(mid, dof) < probability ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

MeanInterval mean_interval(const std::vector<double>& values) {
  MeanInterval out;
  out.n = static_cast<int>(values.size());
  if (out.n == 0) return out;
  for (const double v : values) out.mean += v / out.n;
  if (out.n < 2) return out;
  double squares = 0.0;
  for (const double v : values) squares += (v - out.mean) * (v - out.mean);
  out.standard_deviation = std::sqrt(squares / (out.n - 1));
  out.half_width = student_t_quantile(0.975, out.n - 1) * out.standard_deviation / std::sqrt(out.n);
  return out;
}

PairedTest paired_t_test(const std::vector<double>& a, const std::vector<double>& b) {
  assert(a.size() == b.size());
  std::vector<double> differences(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) differences[i] = a[i] - b[i];
  PairedTest out;
  out.difference = mean_interval(differences);
  if (out.difference.n < 2) return out;
  const double standard_error = out.difference.standard_deviation / std::sqrt(out.difference.n);
  if (standard_error == 0.0) {
    out.t = out.difference.mean == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), out.difference.mean);
    out.p_value = out.difference.mean == 0.0 ? 1.0 : 0.0;
    return out;
  }
  out.t = out.difference.mean / standard_error;
  out.p_value = 2.0 * (1.0 - student_t_cdf(std::abs(out.t), out.difference.n - 1));
  return out;
}

}  // namespace crux
