#include "experiments/transfer_diagnosis.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "experiments/statistics.hpp"

namespace crux {

namespace {

// What the real tries of one agent-space pair (state, tile) have shown so far.
struct Evidence {
  double offset_y = 0, offset_z = 0;  // sums of the holds' offsets from the tile centre
  int tries = 0, successes = 0;
};

std::uint64_t pair_key(const IterationRecord& r) {
  return (static_cast<std::uint64_t>(r.grid_state) << 32) | static_cast<std::uint32_t>(r.tile);
}

void add(std::unordered_map<std::uint64_t, Evidence>& evidence, const IterationRecord& r) {
  if (r.tile == kNoAction) return;
  Evidence& e = evidence[pair_key(r)];
  e.offset_y += r.tile_offset_y;
  e.offset_z += r.tile_offset_z;
  ++e.tries;
  e.successes += r.success;
}

}  // namespace

std::array<ChoiceProfile, kRegimeCount> diagnose_transfer(const ExperimentResult& result, int window) {
  std::array<ChoiceProfile, kRegimeCount> out;
  std::array<std::vector<double>, kRegimeCount> distances;
  std::array<double, kRegimeCount> rise_sum{}, evidence_tries{}, evidence_successes{};
  const auto& training = result.conditions[static_cast<int>(Condition::Training)].runs;
  const auto& transfer = result.conditions[static_cast<int>(Condition::Transfer)].runs;
  for (std::size_t i = 0; i < transfer.size(); ++i) {
    std::unordered_map<std::uint64_t, Evidence> evidence;
    for (const IterationRecord& r : training[i].iterations) add(evidence, r);
    const auto& records = transfer[i].iterations;
    const std::size_t end = std::min(records.size(), static_cast<std::size_t>(window));
    for (std::size_t k = 0; k < end; ++k) {
      const IterationRecord& r = records[k];
      const int regime = static_cast<int>(r.regime);
      ChoiceProfile& p = out[regime];
      ++p.actions;
      p.successes += r.success;
      if (r.success) rise_sum[regime] += 100.0 * r.root_rise_m;
      if (r.back_to_left_hold) ++p.back_to_left_hold, p.back_to_left_hold_successes += r.success;
      const bool repeat = k > 0 && !records[k - 1].success && records[k - 1].hold_id == r.hold_id;
      if (repeat) ++p.repeats_of_failure, p.repeats_of_failure_successes += r.success;
      // A repeat is explained by the failure before it; the evidence measures the others.
      const auto found = repeat || r.tile == kNoAction ? evidence.end() : evidence.find(pair_key(r));
      if (found != evidence.end()) {
        const Evidence& e = found->second;
        ++p.with_evidence;
        evidence_tries[regime] += e.tries;
        evidence_successes[regime] += e.successes;
        const double distance =
            std::hypot(r.tile_offset_y - e.offset_y / e.tries, r.tile_offset_z - e.offset_z / e.tries);
        distances[regime].push_back(100.0 * distance);
        if (distance > kFarFromEvidence) {
          ++p.far, p.far_successes += r.success;
        } else {
          ++p.near, p.near_successes += r.success;
        }
      }
      add(evidence, r);
    }
  }
  for (int regime = 0; regime < kRegimeCount; ++regime) {
    ChoiceProfile& p = out[regime];
    if (p.successes > 0) p.mean_root_rise_cm = rise_sum[regime] / p.successes;
    if (evidence_tries[regime] > 0) p.evidence_success_rate = evidence_successes[regime] / evidence_tries[regime];
    std::vector<double>& d = distances[regime];
    if (!d.empty()) {
      std::sort(d.begin(), d.end());
      p.median_distance_cm = percentile(d, 0.5);
    }
  }
  return out;
}

}  // namespace crux
