#include "climbing/posture_cache.hpp"

#include <algorithm>
#include <vector>

#include "common/checkpoint_stream.hpp"

namespace crux {

void PostureCache::save_state(CheckpointWriter& out) const {
  // In configuration order, so that the file does not depend on hashing.
  std::vector<std::uint64_t> reached;
  for (const auto& [configuration, unused] : reached_) reached.push_back(configuration);
  std::sort(reached.begin(), reached.end());
  out.vector(reached);
  for (const std::uint64_t configuration : reached) {
    const Posture& posture = reached_.at(configuration);
    out.values(posture.data(), static_cast<std::size_t>(posture.size()));
  }
  std::vector<std::uint64_t> unreachable(unreachable_.begin(), unreachable_.end());
  std::sort(unreachable.begin(), unreachable.end());
  out.vector(unreachable);
}

void PostureCache::load_state(CheckpointReader& in) {
  reached_.clear();
  for (const std::uint64_t configuration : in.vector<std::uint64_t>()) {
    const std::vector<double> values = in.vector<double>();
    if (values.size() != static_cast<std::size_t>(Posture::SizeAtCompileTime)) in.fail();
    reached_.emplace(configuration, Eigen::Map<const Posture>(values.data()));
  }
  const std::vector<std::uint64_t> unreachable = in.vector<std::uint64_t>();
  unreachable_ = {unreachable.begin(), unreachable.end()};
}

}  // namespace crux
