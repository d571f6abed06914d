#include "common/counted.hpp"

#include <cstddef>

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(Counted, OneTakesTheSingularEveryOtherCountThePlural) {
  EXPECT_EQ(counted(1, "seed"), "1 seed");
  EXPECT_EQ(counted(2, "seed"), "2 seeds");
  EXPECT_EQ(counted(0, "figure"), "0 figures");
  EXPECT_EQ(counted(-1, "wall"), "-1 walls");
  EXPECT_EQ(counted(std::size_t{1}, "move"), "1 move") << "a size counts too";
}

TEST(Counted, AnIrregularPluralIsNamed) {
  EXPECT_EQ(counted(1, "query", "queries"), "1 query");
  EXPECT_EQ(counted(3, "query", "queries"), "3 queries");
  EXPECT_EQ(counted_noun(1, "entry", "entries"), "entry");
  EXPECT_EQ(counted_noun(7, "entry", "entries"), "entries");
  EXPECT_EQ(counted_noun(7, "IK solve"), "IK solves");
}

}  // namespace
}  // namespace crux
