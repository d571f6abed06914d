#include "configurations/geometric_filter.hpp"

#include <algorithm>
#include <limits>

namespace crux {

namespace {

double height(const Wall& wall, int hold) { return wall.holds[hold].position.z(); }

struct HeightRange {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  int count = 0;
  void add(double z) {
    low = std::min(low, z);
    high = std::max(high, z);
    sum += z;
    ++count;
  }
  double mean() const { return sum / count; }
};

bool crossed(const Wall& wall, int right, int left) {
  return right != kFree && left != kFree && wall.holds[right].position.y() > wall.holds[left].position.y();
}

}  // namespace

bool span_within_reach(const Wall& wall, const HoldConfiguration& c, double max_span_m) {
  const double limit = max_span_m * max_span_m;
  for (int a = 0; a < kLimbCount; ++a) {
    if (c.holds[a] == kFree) continue;
    for (int b = a + 1; b < kLimbCount; ++b) {
      if (c.holds[b] == kFree) continue;
      if ((wall.holds[c.holds[a]].position - wall.holds[c.holds[b]].position).squaredNorm() > limit) return false;
    }
  }
  return true;
}

bool feet_not_above_hands(const Wall& wall, const HoldConfiguration& c, FeetAboveHandsReading reading) {
  HeightRange hands, feet;
  for (const Limb limb : {Limb::RightHand, Limb::LeftHand}) {
    if (c.hold(limb) != kFree) hands.add(height(wall, c.hold(limb)));
  }
  for (const Limb limb : {Limb::RightFoot, Limb::LeftFoot}) {
    if (c.hold(limb) != kFree) feet.add(height(wall, c.hold(limb)));
  }
  if (hands.count == 0 || feet.count == 0) return true;
  switch (reading) {
    case FeetAboveHandsReading::LowestFootAboveHighestHand:
      return !(feet.low > hands.high);
    case FeetAboveHandsReading::LowestFootAboveLowestHand:
      return !(feet.low > hands.low);
    case FeetAboveHandsReading::HighestFootAboveLowestHand:
      return !(feet.high > hands.low);
    case FeetAboveHandsReading::MeanFeetAboveMeanHands:
      return !(feet.mean() > hands.mean());
  }
  return true;
}

bool arms_not_crossed(const Wall& wall, const HoldConfiguration& c) {
  return !crossed(wall, c.hold(Limb::RightHand), c.hold(Limb::LeftHand));
}

bool legs_not_crossed(const Wall& wall, const HoldConfiguration& c) {
  return !crossed(wall, c.hold(Limb::RightFoot), c.hold(Limb::LeftFoot));
}

bool passes_filter(const Wall& wall, const HoldConfiguration& c, const FilterParameters& parameters) {
  return (!parameters.reject_crossed_arms || arms_not_crossed(wall, c)) &&
         (!parameters.reject_crossed_legs || legs_not_crossed(wall, c)) &&
         feet_not_above_hands(wall, c, parameters.feet_above_hands) &&
         span_within_reach(wall, c, parameters.max_span_m);
}

}  // namespace crux
