#pragma once
// The cache of section III-C: every 4-configuration solved on a wall, with the posture
// that reaches it, so that IK runs once per 4-configuration. Unreachable verdicts are
// cached too (on by default): the paper's reachability does not depend on the path
// (its G-reachability hypothesis; docs/MODEL.md, choice C11), so solving again could only repeat the
// verdict at the price of a full time-out.

#include <cstdint>
#include <unordered_map>
#include <unordered_set>

#include "body/body_model.hpp"

namespace crux {

class CheckpointWriter;
class CheckpointReader;

class PostureCache {
 public:
  const Posture* reached(std::uint64_t configuration) const {
    const auto it = reached_.find(configuration);
    return it == reached_.end() ? nullptr : &it->second;
  }
  bool known_unreachable(std::uint64_t configuration) const { return unreachable_.contains(configuration); }

  void store_reached(std::uint64_t configuration, const Posture& posture) { reached_.emplace(configuration, posture); }
  void store_unreachable(std::uint64_t configuration) { unreachable_.insert(configuration); }

  std::size_t reached_count() const { return reached_.size(); }
  std::size_t unreachable_count() const { return unreachable_.size(); }

  // Every verdict, for a run's checkpoint (load_state replaces them).
  void save_state(CheckpointWriter& out) const;
  void load_state(CheckpointReader& in);

 private:
  std::unordered_map<std::uint64_t, Posture> reached_;
  std::unordered_set<std::uint64_t> unreachable_;
};

// A posture's doubles in a checkpoint; load_posture fails the reader on another size.
void save_posture(CheckpointWriter& out, const Posture& posture);
Posture load_posture(CheckpointReader& in);

}  // namespace crux
