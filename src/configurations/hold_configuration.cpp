#include "configurations/hold_configuration.hpp"

namespace crux {

Limb HoldConfiguration::free_limb() const {
  for (int limb = 0; limb < kLimbCount; ++limb) {
    if (holds[limb] == kFree) return static_cast<Limb>(limb);
  }
  return Limb::RightHand;
}

int HoldConfiguration::free_count() const {
  int count = 0;
  for (const int hold : holds) count += hold == kFree;
  return count;
}

std::uint64_t encode(const HoldConfiguration& configuration, int hold_count) {
  const std::uint64_t base = static_cast<std::uint64_t>(hold_count) + 1;
  std::uint64_t code = 0;
  for (int limb = kLimbCount - 1; limb >= 0; --limb) {
    code = code * base + static_cast<std::uint64_t>(configuration.holds[limb] + 1);
  }
  return code;
}

HoldConfiguration decode_configuration(std::uint64_t code, int hold_count) {
  const std::uint64_t base = static_cast<std::uint64_t>(hold_count) + 1;
  HoldConfiguration configuration;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    configuration.holds[limb] = static_cast<int>(code % base) - 1;
    code /= base;
  }
  return configuration;
}

}  // namespace crux
