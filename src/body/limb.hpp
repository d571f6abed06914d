#pragma once
// The four limbs that grasp holds, in the order of a hold configuration (right hand,
// left hand, right foot, left foot), and the operational points E = (e0, e1, e2, e3, e4)
// of section III-A: the root, then the limbs in that order.

#include "common/enum_names.hpp"

namespace crux {

inline constexpr int kLimbCount = 4;
inline constexpr int kOperationalPointCount = 1 + kLimbCount;
enum class Limb : int { RightHand = 0, LeftHand = 1, RightFoot = 2, LeftFoot = 3 };

// right_hand, left_hand, right_foot, left_foot: the names of files and outputs; parsing
// also takes the short forms rh, lh, rf, lf.
template <>
struct EnumNames<Limb> {
  static constexpr std::array<EnumName<Limb>, 4> entries{{{Limb::RightHand, "right_hand", "rh"},
                                                          {Limb::LeftHand, "left_hand", "lh"},
                                                          {Limb::RightFoot, "right_foot", "rf"},
                                                          {Limb::LeftFoot, "left_foot", "lf"}}};
};

constexpr bool is_hand(Limb limb) { return limb == Limb::RightHand || limb == Limb::LeftHand; }

// The index of a limb's grasp point among the operational points (e0 is index 0).
constexpr int operational_point(Limb limb) { return 1 + static_cast<int>(limb); }
constexpr int operational_point(int limb) { return 1 + limb; }

}  // namespace crux
