#include "learning/deterministic_model.hpp"

namespace crux {

void DeterministicModel::record(const Experience& experience) {
  const auto [it, inserted] = index_.try_emplace(PairKey{experience.wall_state, experience.wall_action}, entries_.size());
  if (inserted) {
    entries_.push_back(experience);
    order_.push_back(it->second);
  } else {
    entries_[it->second] = experience;
  }
}

}  // namespace crux
