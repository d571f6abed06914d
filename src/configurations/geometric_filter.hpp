#pragma once
// The geometric filter of section III-C: configurations that are not geometrically
// meaningful are left out of learning. Each rule is a named predicate with its threshold
// a parameter; the free limb of a 3-configuration takes part in no rule.

#include <array>

#include "common/enum_names.hpp"
#include "configurations/hold_configuration.hpp"
#include "wall/wall.hpp"

namespace crux {

// Readings of the paper's "both feet above the hands" (docs/MODEL.md, choice C13); docs/DESIGN.md
// compares their pass rates with the paper's. Each compares the heights of the held feet
// with those of the held hands and rejects when:
enum class FeetAboveHandsReading {
  LowestFootAboveHighestHand,  // every foot is above every hand
  LowestFootAboveLowestHand,   // both feet are above at least one hand
  HighestFootAboveLowestHand,  // some foot is above some hand (feet must stay below both hands)
  MeanFeetAboveMeanHands,      // the feet's mean height is above the hands'
};
inline constexpr std::array<FeetAboveHandsReading, 4> kFeetAboveHandsReadings{
    FeetAboveHandsReading::LowestFootAboveHighestHand, FeetAboveHandsReading::LowestFootAboveLowestHand,
    FeetAboveHandsReading::HighestFootAboveLowestHand, FeetAboveHandsReading::MeanFeetAboveMeanHands};
template <>
struct EnumNames<FeetAboveHandsReading> {
  static constexpr std::array<EnumName<FeetAboveHandsReading>, 4> entries{
      {{FeetAboveHandsReading::LowestFootAboveHighestHand, "lowest-foot-above-highest-hand"},
       {FeetAboveHandsReading::LowestFootAboveLowestHand, "lowest-foot-above-lowest-hand"},
       {FeetAboveHandsReading::HighestFootAboveLowestHand, "highest-foot-above-lowest-hand"},
       {FeetAboveHandsReading::MeanFeetAboveMeanHands, "mean-feet-above-mean-hands"}}};
};

struct FilterParameters {
  double max_span_m = 2.8;  // the climber's maximal extension (upper bound)
  // The reading closest to the paper's pass rates (docs/DESIGN.md).
  FeetAboveHandsReading feet_above_hands = FeetAboveHandsReading::HighestFootAboveLowestHand;
  bool reject_crossed_arms = true;
  bool reject_crossed_legs = true;
};

// Each predicate is true when the configuration is acceptable under that rule.
bool span_within_reach(const Wall& wall, const HoldConfiguration& c, double max_span_m);
bool feet_not_above_hands(const Wall& wall, const HoldConfiguration& c, FeetAboveHandsReading reading);
// Crossed: the right limb's hold lies to the left (larger y) of the left limb's.
bool arms_not_crossed(const Wall& wall, const HoldConfiguration& c);
bool legs_not_crossed(const Wall& wall, const HoldConfiguration& c);

bool passes_filter(const Wall& wall, const HoldConfiguration& c, const FilterParameters& parameters);

}  // namespace crux
