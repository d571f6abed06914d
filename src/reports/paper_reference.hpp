#pragma once
// The paper's own numbers that crux prints beside its results, in one place.

#include "climbing/climbing_mdp.hpp"

namespace crux {

// Section IV, Table I: [condition: training, transfer][window: beginning, overall][regime].
struct PaperTableOne {
  double vertical_cm[2][2][kRegimeCount];
  double success_rate[2][2][kRegimeCount];  // fractions
};
const PaperTableOne& paper_table_one();

// Section III-C: shares of 3- and 4-configurations that pass the geometric filter.
inline constexpr double kPaperFilterPass3 = 0.073;
inline constexpr double kPaperFilterPass4 = 0.014;

// Section IV: an optimal climb of a random wall takes about this many actions.
inline constexpr int kPaperOptimalClimbLength = 10;

}  // namespace crux
