#include "reports/paper_reference.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

// Table I of Libeau, Micaelli & Sigaud (2009) as printed: rows w-greedy, g-greedy,
// random; columns beginning training, beginning transfer, overall training, overall
// transfer. The stored table is indexed [condition][window][regime], so a transposition
// there shows up here.
constexpr double kPrintedVerticalCm[3][4] = {{7.3, 12.0, 9.4, 10.6}, {0.4, 1.8, 4.3, 3.4}, {2.0, 2.0, 2.0, 2.0}};
constexpr double kPrintedSuccessPercent[3][4] = {{100, 100, 100, 100}, {46, 45, 60, 57}, {43, 44, 43, 44}};

TEST(PaperReference, TableOneIsThePapersTableOne) {
  const PaperTableOne& paper = paper_table_one();
  for (int regime = 0; regime < kRegimeCount; ++regime) {
    for (int window = 0; window < 2; ++window) {
      for (int condition = 0; condition < 2; ++condition) {
        const int column = 2 * window + condition;
        EXPECT_DOUBLE_EQ(paper.vertical_cm[condition][window][regime], kPrintedVerticalCm[regime][column])
            << "regime " << regime << ", column " << column;
        EXPECT_NEAR(paper.success_rate[condition][window][regime], kPrintedSuccessPercent[regime][column] / 100.0,
                    1e-12)
            << "regime " << regime << ", column " << column;
      }
    }
  }
}

TEST(PaperReference, ASampleOfCellsByName) {
  const PaperTableOne& paper = paper_table_one();
  constexpr int training = 0, transfer = 1, beginning = 0, overall = 1;
  constexpr int w = static_cast<int>(Regime::WGreedy), g = static_cast<int>(Regime::GGreedy);
  // Section IV: g-greedy actions at the beginning of transfer rise more than in training.
  EXPECT_EQ(paper.vertical_cm[transfer][beginning][g], 1.8);
  EXPECT_EQ(paper.vertical_cm[training][beginning][g], 0.4);
  EXPECT_EQ(paper.vertical_cm[transfer][beginning][w], 12.0);
  EXPECT_EQ(paper.success_rate[training][overall][g], 0.60);
  EXPECT_EQ(paper.success_rate[transfer][overall][g], 0.57);
  EXPECT_EQ(paper.success_rate[transfer][beginning][w], 1.0) << "w-greedy actions always succeed";
}

TEST(PaperReference, FilterSharesAndOptimalClimbOfTheText) {
  // Section III-C: "only 7.3% of the possible 3-configurations and 1.4% of the
  // 4-configurations pass the test"; section IV: an optimal climb takes "around 10 actions".
  EXPECT_DOUBLE_EQ(kPaperFilterPass3, 0.073);
  EXPECT_DOUBLE_EQ(kPaperFilterPass4, 0.014);
  EXPECT_EQ(kPaperOptimalClimbLength, 10);
}

}  // namespace
}  // namespace crux
