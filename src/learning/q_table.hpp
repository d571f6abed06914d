#pragma once
// A Q-table over integer states and actions: sparse in states (a row is created when a
// state's value is first written), dense in actions. Unwritten values are 0, the
// initial value of every Q-table here (docs/MODEL.md, choice C18). It also counts, per pair, the real
// experiences of it, which is what "already taken" means in Algorithm 3.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <absl/container/flat_hash_map.h>

namespace crux {

class CheckpointWriter;
class CheckpointReader;

using StateCode = std::uint64_t;
using ActionCode = std::int32_t;
inline constexpr ActionCode kNoAction = -1;

class QTable {
 public:
  explicit QTable(int action_count);

  int action_count() const { return action_count_; }
  std::size_t state_count() const { return rows_.size(); }

  // The look-ups of every Q-learning update: inline, since planning makes 50 per step.
  double value(StateCode s, ActionCode a) const {
    const double* row = row_values(s);
    return row == nullptr ? 0.0 : row[a];
  }
  std::uint32_t visits(StateCode s, ActionCode a) const;
  bool taken(StateCode s, ActionCode a) const { return visits(s, a) > 0; }

  void set_value(StateCode s, ActionCode a, double value);
  // Q(s, a) to read and write in one look-up, creating s's row; valid until the next
  // row is created.
  double& value_slot(StateCode s, ActionCode a) { return values_[row_of(s) * action_count_ + a]; }
  void add_visit(StateCode s, ActionCode a);
  void set_visits(StateCode s, ActionCode a, std::uint32_t visits);

  // max over `available` of Q(s, a); 0 when nothing is available.
  double best_value(StateCode s, std::span<const ActionCode> available) const {
    if (available.empty()) return 0.0;
    const double* row = row_values(s);
    if (row == nullptr) return 0.0;
    double best = row[available[0]];
    for (const ActionCode a : available.subspan(1)) best = std::max(best, row[a]);
    return best;
  }

  // The whole table, rows in creation order, for a run's checkpoint; load_state
  // replaces this table's contents (same action count, or the reader fails).
  void save_state(CheckpointWriter& out) const;
  void load_state(CheckpointReader& in);

  // Every stored row, in increasing state order (for files and maps).
  void for_each_row(
      const std::function<void(StateCode, std::span<const double>, std::span<const std::uint32_t>)>& visit) const;

 private:
  std::size_t row_of(StateCode s);  // creates the row
  const double* row_values(StateCode s) const {
    const auto it = rows_.find(s);
    return it == rows_.end() ? nullptr : values_.data() + it->second * action_count_;
  }

  int action_count_;
  absl::flat_hash_map<StateCode, std::size_t> rows_;
  std::vector<double> values_;
  std::vector<std::uint32_t> visits_;
};

}  // namespace crux
