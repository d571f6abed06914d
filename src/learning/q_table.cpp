#include "learning/q_table.hpp"

#include <algorithm>
#include <cassert>

#include "common/checkpoint_stream.hpp"

namespace crux {

QTable::QTable(int action_count) : action_count_(action_count) { assert(action_count > 0); }

std::size_t QTable::row_of(StateCode s) {
  const auto [it, inserted] = rows_.try_emplace(s, rows_.size());
  if (inserted) {
    values_.resize(values_.size() + action_count_, 0.0);
    visits_.resize(visits_.size() + action_count_, 0);
  }
  return it->second;
}

std::uint32_t QTable::visits(StateCode s, ActionCode a) const {
  const auto it = rows_.find(s);
  return it == rows_.end() ? 0 : visits_[it->second * action_count_ + a];
}

void QTable::set_value(StateCode s, ActionCode a, double value) { value_slot(s, a) = value; }

void QTable::add_visit(StateCode s, ActionCode a) { ++visits_[row_of(s) * action_count_ + a]; }

void QTable::set_visits(StateCode s, ActionCode a, std::uint32_t visits) {
  visits_[row_of(s) * action_count_ + a] = visits;
}

void QTable::save_state(CheckpointWriter& out) const {
  out.value<std::int64_t>(action_count_);
  std::vector<StateCode> states(rows_.size());
  for (const auto& [state, row] : rows_) states[row] = state;
  out.vector(states);
  out.vector(values_);
  out.vector(visits_);
}

void QTable::load_state(CheckpointReader& in) {
  if (in.value<std::int64_t>() != action_count_) in.fail();
  const std::vector<StateCode> states = in.vector<StateCode>();
  std::vector<double> values = in.vector<double>();
  std::vector<std::uint32_t> visits = in.vector<std::uint32_t>();
  if (values.size() != states.size() * action_count_ || visits.size() != values.size()) in.fail();
  rows_.clear();
  for (std::size_t row = 0; row < states.size(); ++row) {
    if (!rows_.emplace(states[row], row).second) in.fail();
  }
  values_ = std::move(values);
  visits_ = std::move(visits);
}

void QTable::for_each_row(
    const std::function<void(StateCode, std::span<const double>, std::span<const std::uint32_t>)>& visit) const {
  std::vector<std::pair<StateCode, std::size_t>> ordered(rows_.begin(), rows_.end());
  std::sort(ordered.begin(), ordered.end());
  for (const auto& [state, row] : ordered) {
    visit(state, std::span<const double>(values_.data() + row * action_count_, action_count_),
          std::span<const std::uint32_t>(visits_.data() + row * action_count_, action_count_));
  }
}

}  // namespace crux
