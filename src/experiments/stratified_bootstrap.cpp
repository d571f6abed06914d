#include "experiments/stratified_bootstrap.hpp"

#include <cassert>
#include <cmath>
#include <limits>

namespace crux {

namespace {

// The trimmed mean of a buffer the caller lets us reorder: the bootstrap calls it once per
// replicate on a reused buffer, so no allocation per replicate.
double trimmed_mean_in_place(std::span<double> values, double proportion_to_cut) {
  assert(proportion_to_cut >= 0.0 && proportion_to_cut < 0.5);
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t cut = static_cast<std::size_t>(proportion_to_cut * static_cast<double>(values.size()));
  // Two partial partitions (scipy's own approach) put the kept values in the middle,
  // unordered, without a full sort.
  if (cut > 0) {
    std::nth_element(values.begin(), values.begin() + cut, values.end());
    std::nth_element(values.begin() + cut, values.end() - cut, values.end());
  }
  double sum = 0.0;
  for (std::size_t i = cut; i < values.size() - cut; ++i) sum += values[i];
  return sum / static_cast<double>(values.size() - 2 * cut);
}

constexpr double kInterquartileCut = 0.25;

}  // namespace

double trimmed_mean(std::span<const double> values, double proportion_to_cut) {
  std::vector<double> copy(values.begin(), values.end());
  return trimmed_mean_in_place(copy, proportion_to_cut);
}

double interquartile_mean(std::span<const double> values) { return trimmed_mean(values, kInterquartileCut); }

Strata strata_of(const std::vector<std::size_t>& stratum_of_value) {
  // A linear search over the ids seen so far, as cluster_means: tens of walls.
  std::vector<std::size_t> ids;
  std::vector<std::vector<std::size_t>> members;
  for (std::size_t i = 0; i < stratum_of_value.size(); ++i) {
    const std::size_t k =
        static_cast<std::size_t>(std::find(ids.begin(), ids.end(), stratum_of_value[i]) - ids.begin());
    if (k == ids.size()) {
      ids.push_back(stratum_of_value[i]);
      members.emplace_back();
    }
    members[k].push_back(i);
  }
  Strata out;
  out.starts.push_back(0);
  for (const auto& m : members) {
    out.order.insert(out.order.end(), m.begin(), m.end());
    out.starts.push_back(out.order.size());
  }
  return out;
}

double probability_of_improvement(std::span<const double> x, std::span<const double> y,
                                  std::span<const std::size_t> starts, bool higher_is_better) {
  assert(x.size() == y.size() && !starts.empty() && starts.back() == x.size());
  const std::size_t strata = starts.size() - 1;
  if (strata == 0) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (std::size_t k = 0; k < strata; ++k) {
    double wins = 0.0;
    for (std::size_t i = starts[k]; i < starts[k + 1]; ++i) {
      for (std::size_t j = starts[k]; j < starts[k + 1]; ++j) {
        if (x[i] == y[j]) {
          wins += 0.5;
        } else if ((x[i] > y[j]) == higher_is_better) {
          wins += 1.0;
        }
      }
    }
    const double size = static_cast<double>(starts[k + 1] - starts[k]);
    sum += wins / (size * size);
  }
  return sum / static_cast<double>(strata);
}

StratifiedBootstrap::StratifiedBootstrap(std::vector<std::size_t> starts, RandomStream stream, int replicates)
    : starts_(std::move(starts)), stream_(stream), replicates_(replicates) {
  assert(!starts_.empty() && starts_.front() == 0 && std::is_sorted(starts_.begin(), starts_.end()));
  assert(replicates_ > 0);
}

void StratifiedBootstrap::resample(std::uint64_t replicate, std::vector<std::size_t>& positions) const {
  for (std::size_t k = 0; k + 1 < starts_.size(); ++k) {
    const std::size_t size = starts_[k + 1] - starts_[k];
    for (std::size_t i = starts_[k]; i < starts_[k + 1]; ++i)
      positions[i] = starts_[k] + stream_.below(size, replicate, i);
  }
}

StratifiedComparison stratified_comparison(const std::vector<double>& a, const std::vector<double>& b,
                                           const std::vector<std::size_t>& stratum_of_pair, bool higher_is_better,
                                           const RandomStream& stream, int replicates) {
  assert(a.size() == b.size() && a.size() == stratum_of_pair.size());
  const Strata strata = strata_of(stratum_of_pair);
  std::vector<double> grouped_a, grouped_b, grouped_difference;
  for (const std::size_t i : strata.order) {
    grouped_a.push_back(a[i]);
    grouped_b.push_back(b[i]);
    grouped_difference.push_back(a[i] - b[i]);
  }
  const StratifiedBootstrap bootstrap(strata.starts, stream, replicates);
  // Buffers reused by every replicate.
  std::vector<double> drawn(a.size()), drawn_b(a.size());
  const auto iqm_of = [&](const std::vector<double>& values) {
    return bootstrap.estimate([&](std::span<const std::size_t> positions) {
      for (std::size_t i = 0; i < positions.size(); ++i) drawn[i] = values[positions[i]];
      return trimmed_mean_in_place(drawn, kInterquartileCut);
    });
  };
  StratifiedComparison out;
  out.iqm_a = iqm_of(grouped_a);
  out.iqm_b = iqm_of(grouped_b);
  out.iqm_difference = iqm_of(grouped_difference);
  out.probability_of_improvement = bootstrap.estimate([&](std::span<const std::size_t> positions) {
    for (std::size_t i = 0; i < positions.size(); ++i) {
      drawn[i] = grouped_a[positions[i]];
      drawn_b[i] = grouped_b[positions[i]];
    }
    return probability_of_improvement(drawn, drawn_b, strata.starts, higher_is_better);
  });
  for (std::size_t k = 0; k + 1 < strata.starts.size(); ++k) {
    if (strata.starts[k + 1] - strata.starts[k] >= 2) out.has_intervals = true;
  }
  if (!out.has_intervals) {
    for (BootstrapEstimate* e : {&out.iqm_a, &out.iqm_b, &out.iqm_difference, &out.probability_of_improvement}) {
      e->low = e->high = std::numeric_limits<double>::quiet_NaN();
    }
  }
  return out;
}

}  // namespace crux
