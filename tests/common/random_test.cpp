#include "common/random.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(Random, EngineIsTheStandardsMt19937_64) {
  // The C++ standard fixes the 10000th output of a default-seeded mt19937_64.
  std::mt19937_64 reference;
  reference.discard(9999);
  EXPECT_EQ(reference(), 9981545732273789042ULL);
}

TEST(Random, SameSeedSameStream) {
  Random a(42), b(42), c(43);
  for (int i = 0; i < 100; ++i) {
    const double x = a.normal();
    EXPECT_EQ(x, b.normal());
    (void)c;
  }
  EXPECT_NE(Random(42).uniform(), Random(43).uniform());
}

TEST(Random, UniformIsInUnitIntervalAndBelowIsUnbiasedInRange) {
  Random random(3);
  int counts[3] = {0, 0, 0};
  for (int i = 0; i < 30000; ++i) {
    const double u = random.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    ++counts[random.below(3)];
  }
  for (int c : counts) EXPECT_NEAR(c, 10000, 400);  // about 4.6 standard deviations
}

TEST(Random, NormalHasUnitMoments) {
  Random random(5);
  double sum = 0, squares = 0;
  constexpr int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = random.normal();
    sum += x;
    squares += x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(squares / n, 1.0, 0.01);
}

TEST(Random, DerivedSeedsDifferByIndex) {
  EXPECT_NE(derive_seed(1, 0), derive_seed(1, 1));
  EXPECT_NE(derive_seed(1, 0), derive_seed(2, 0));
  EXPECT_EQ(derive_seed(9, 4), derive_seed(9, 4));
}

}  // namespace
}  // namespace crux
