#include "climbing/posture_cache.hpp"

#include <algorithm>
#include <vector>

#include "common/checkpoint_stream.hpp"

namespace crux {

void save_posture(CheckpointWriter& out, const Posture& posture) {
  out.values(posture.data(), static_cast<std::size_t>(posture.size()));
}

Posture load_posture(CheckpointReader& in) {
  const std::vector<double> values = in.vector<double>();
  if (values.size() != static_cast<std::size_t>(Posture::SizeAtCompileTime)) in.fail();
  return Eigen::Map<const Posture>(values.data());
}

void PostureCache::save_state(CheckpointWriter& out) const {
  const std::vector<std::uint64_t> reached = sorted_keys(reached_);
  out.vector(reached);
  for (const std::uint64_t configuration : reached) save_posture(out, reached_.at(configuration));
  std::vector<std::uint64_t> unreachable(unreachable_.begin(), unreachable_.end());
  std::sort(unreachable.begin(), unreachable.end());
  out.vector(unreachable);
}

void PostureCache::load_state(CheckpointReader& in) {
  reached_.clear();
  for (const std::uint64_t configuration : in.vector<std::uint64_t>())
    reached_.emplace(configuration, load_posture(in));
  const std::vector<std::uint64_t> unreachable = in.vector<std::uint64_t>();
  unreachable_ = {unreachable.begin(), unreachable.end()};
}

}  // namespace crux
