#pragma once
// rliable's statistics (Agarwal, Schwarzer, Castro, Courville and Bellemare, "Deep
// reinforcement learning at the edge of the statistical precipice", NeurIPS 2021): the
// interquartile mean, the probability of improvement, and the stratified bootstrap that
// gives both an interval. The strata are rliable's tasks (here walls): a resample keeps
// every stratum and draws its runs (learning seeds) with replacement, so the intervals
// speak for these walls and do not cover wall-to-wall variation (the t-interval over
// walls of statistics.hpp does).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "common/random_stream.hpp"
#include "experiments/statistics.hpp"

namespace crux {

// scipy.stats.trim_mean(values, proportion_to_cut): the mean of the values left after
// cutting int(proportion_to_cut x n) of the smallest and as many of the largest (no
// fractional trimming: with 0.25, 3 values keep all, 5 or 6 lose one at each end). NaN
// when empty.
double trimmed_mean(std::span<const double> values, double proportion_to_cut);

// The interquartile mean (rliable's IQM): trimmed_mean(values, 0.25).
double interquartile_mean(std::span<const double> values);

// Positions of a sample grouped by stratum: stratum k holds positions
// [starts[k], starts[k + 1]) of a grouped sample, so starts has one entry more than there
// are strata. `order` lists, for each grouped position, the value's index in the input.
struct Strata {
  std::vector<std::size_t> order;
  std::vector<std::size_t> starts;
};
// Strata in order of first appearance in stratum_of_value, values in input order within.
Strata strata_of(const std::vector<std::size_t>& stratum_of_value);

// rliable's probability of improvement, P(x beats y): per stratum, the Mann-Whitney
// statistic of its x values against its y values (a pair counts 1 when x is better, 1/2
// when tied) divided by the number of pairs, then the mean over strata. x and y are
// grouped by the same `starts` (paired runs: as many of each per stratum). Better is
// higher when `higher_is_better`, lower otherwise.
double probability_of_improvement(std::span<const double> x, std::span<const double> y,
                                  std::span<const std::size_t> starts, bool higher_is_better);

struct BootstrapEstimate {
  double value = 0.0;  // the statistic of the sample itself
  double low = 0.0;    // 2.5 % and 97.5 % percentiles of the statistic over the replicates
  double high = 0.0;
};

// rliable's stratified bootstrap with its percentile interval. Replicate r replaces slot i
// of stratum k by a position drawn uniformly from stratum k, using draw (r, i) of
// `stream`: a pure function of the stream, so the same stream gives the same interval,
// and every statistic estimated with one bootstrap sees the same resamples. A stratum of
// one value always resamples to itself.
class StratifiedBootstrap {
 public:
  StratifiedBootstrap(std::vector<std::size_t> starts, RandomStream stream, int replicates);

  // statistic(positions) -> double, positions (grouped by stratum like the sample's) into
  // the grouped sample. The position buffer is reused across replicates.
  template <typename Statistic>
  BootstrapEstimate estimate(Statistic&& statistic) const {
    std::vector<std::size_t> positions(starts_.back());
    std::iota(positions.begin(), positions.end(), std::size_t{0});
    BootstrapEstimate out;
    out.value = statistic(std::span<const std::size_t>(positions));
    std::vector<double> replicates(static_cast<std::size_t>(replicates_));
    for (std::size_t r = 0; r < replicates.size(); ++r) {
      resample(r, positions);
      replicates[r] = statistic(std::span<const std::size_t>(positions));
    }
    std::sort(replicates.begin(), replicates.end());
    out.low = percentile(replicates, 0.025);
    out.high = percentile(replicates, 0.975);
    return out;
  }

  const std::vector<std::size_t>& starts() const { return starts_; }

 private:
  void resample(std::uint64_t replicate, std::vector<std::size_t>& positions) const;

  std::vector<std::size_t> starts_;
  RandomStream stream_;
  int replicates_;
};

inline constexpr int kStratifiedBootstrapReplicates = 2000;

// What a StratifiedComparison's intervals resample, or why it has none, in the printed
// report and summary.json.
inline constexpr const char* kStratifiedIntervals = "seeds resampled within walls";
inline constexpr const char* kNoStratifiedIntervals =
    "one seed per wall leaves the stratified bootstrap nothing to resample";

// rliable's view of a paired comparison of a (transfer) against b (control), pair i on
// stratum stratum_of_pair[i]: the IQM of a's runs, of b's, and of the pair differences
// a - b, and P(a beats b), each with its stratified bootstrap interval. A resample draws
// pairs (learning seeds), so a and b keep their pairing within it. With one pair per
// stratum (one seed per wall) every resample is the sample: there is no interval, and the
// estimates' low and high are NaN rather than a zero-width interval that would read as
// certainty.
struct StratifiedComparison {
  BootstrapEstimate iqm_a, iqm_b, iqm_difference, probability_of_improvement;
  bool has_intervals = false;  // some stratum holds two pairs or more
};
StratifiedComparison stratified_comparison(const std::vector<double>& a, const std::vector<double>& b,
                                           const std::vector<std::size_t>& stratum_of_pair, bool higher_is_better,
                                           const RandomStream& stream, int replicates = kStratifiedBootstrapReplicates);

}  // namespace crux
