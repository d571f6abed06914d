#include "learning/deterministic_model.hpp"

#include <algorithm>

namespace crux {

std::size_t DeterministicModel::record(const Experience& experience) {
  const auto [it, inserted] = index_.try_emplace(PairKey{experience.wall_state, experience.wall_action}, entries_.size());
  const std::size_t index = it->second;
  if (!track_predecessors_) {
    if (inserted) entries_.push_back(experience);
    else entries_[index] = experience;
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

}  // namespace crux
