#include "learning/deterministic_model.hpp"

#include <algorithm>

#include "common/checkpoint_stream.hpp"

namespace crux {

const Experience* DeterministicModel::find(StateCode wall_state, ActionCode wall_action) const {
  const auto it = index_.find(PairKey{wall_state, wall_action});
  return it == index_.end() ? nullptr : &entries_[it->second];
}

std::size_t DeterministicModel::record(const Experience& experience) {
  const auto [it, inserted] =
      index_.try_emplace(PairKey{experience.wall_state, experience.wall_action}, entries_.size());
  const std::size_t index = it->second;
  if (!track_predecessors_) {
    if (inserted)
      entries_.push_back(experience);
    else
      entries_[index] = experience;
    return index;
  }
  if (inserted) {
    entries_.push_back(experience);
  } else {
    Experience& known = entries_[index];
    const bool moved = known.next_wall_state != experience.next_wall_state;
    if (moved) {
      std::vector<std::size_t>& old = predecessors_[known.next_wall_state];
      old.erase(std::find(old.begin(), old.end(), index));
    }
    known = experience;
    if (!moved) return index;
  }
  predecessors_[experience.next_wall_state].push_back(index);
  return index;
}

std::span<const std::size_t> DeterministicModel::predecessors(StateCode wall_state) const {
  const auto it = predecessors_.find(wall_state);
  return it == predecessors_.end() ? std::span<const std::size_t>() : std::span<const std::size_t>(it->second);
}

void DeterministicModel::save_state(CheckpointWriter& out) const {
  out.value<std::uint8_t>(track_predecessors_ ? 1 : 0);
  out.vector(entries_);
  // Predecessor lists in state order: the file does not depend on the hash map's.
  const std::vector<StateCode> states = sorted_keys(predecessors_);
  out.vector(states);
  for (const StateCode state : states) out.vector(predecessors_.at(state));
}

void DeterministicModel::load_state(CheckpointReader& in, int wall_actions, int grid_actions) {
  if (in.flag() != track_predecessors_) in.fail();
  entries_ = in.vector<Experience>();
  index_.clear();
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const Experience& e = entries_[i];
    if (e.wall_action < 0 || e.wall_action >= wall_actions || e.grid_action < kNoAction ||
        e.grid_action >= grid_actions) {
      in.fail();
    }
    if (!index_.emplace(PairKey{entries_[i].wall_state, entries_[i].wall_action}, i).second) in.fail();
  }
  predecessors_.clear();
  for (const StateCode state : in.vector<StateCode>()) {
    std::vector<std::size_t> list = in.vector<std::size_t>();
    for (const std::size_t entry : list) {
      if (entry >= entries_.size()) in.fail();
    }
    predecessors_[state] = std::move(list);
  }
}

}  // namespace crux
