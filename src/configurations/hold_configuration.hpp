#pragma once
// Hold configurations (paper, section III-C): which hold each limb grasps, in limb
// order (right hand, left hand, right foot, left foot). A 4-configuration has all four
// limbs on distinct holds; a 3-configuration has one free limb, stored as kFree.

#include <array>
#include <cstdint>

#include "body/body_model.hpp"

namespace crux {

inline constexpr int kFree = -1;  // a limb holding nothing

struct HoldConfiguration {
  std::array<int, kLimbCount> holds{kFree, kFree, kFree, kFree};  // hold indices or kFree

  int hold(Limb limb) const { return holds[static_cast<int>(limb)]; }
  // The free limb of a 3-configuration (the first free one).
  Limb free_limb() const;
  int free_count() const;
  bool operator==(const HoldConfiguration&) const = default;

  // The 4-configuration reached when the free limb takes `hold`.
  HoldConfiguration with(Limb limb, int hold) const {
    HoldConfiguration out = *this;
    out.holds[static_cast<int>(limb)] = hold;
    return out;
  }
};

// Compact integer code: sum over limbs of (hold + 1) * (n + 1)^limb, so that kFree is
// digit 0. Unique for a given hold count n; fits 64 bits for n < 65535.
std::uint64_t encode(const HoldConfiguration& configuration, int hold_count);
HoldConfiguration decode_configuration(std::uint64_t code, int hold_count);

// The round robin of the free limb: right hand, left hand, right foot, left foot, ...
inline Limb next_free_limb(Limb limb) { return static_cast<Limb>((static_cast<int>(limb) + 1) % kLimbCount); }

}  // namespace crux
