#include "reports/paper_reference.hpp"

namespace crux {

const PaperTableOne& paper_table_one() {
  // Regimes in the order w-greedy, g-greedy, random.
  static const PaperTableOne table{
      {{{7.3, 0.4, 2.0}, {9.4, 4.3, 2.0}}, {{12.0, 1.8, 2.0}, {10.6, 3.4, 2.0}}},
      {{{1.00, 0.46, 0.43}, {1.00, 0.60, 0.43}}, {{1.00, 0.45, 0.44}, {1.00, 0.57, 0.44}}}};
  return table;
}

}  // namespace crux
