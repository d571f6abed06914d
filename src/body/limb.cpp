#include "body/limb.hpp"

namespace crux {

const char* limb_name(Limb limb) {
  switch (limb) {
    case Limb::RightHand:
      return "right_hand";
    case Limb::LeftHand:
      return "left_hand";
    case Limb::RightFoot:
      return "right_foot";
    case Limb::LeftFoot:
      return "left_foot";
  }
  return "?";
}

std::optional<Limb> parse_limb(std::string_view name) {
  static constexpr std::string_view short_names[kLimbCount] = {"rh", "lh", "rf", "lf"};
  for (int limb = 0; limb < kLimbCount; ++limb) {
    if (name == limb_name(static_cast<Limb>(limb)) || name == short_names[limb]) return static_cast<Limb>(limb);
  }
  return std::nullopt;
}

}  // namespace crux
