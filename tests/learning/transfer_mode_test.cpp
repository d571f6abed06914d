#include "learning/transfer_mode.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(TransferMode, EveryModeParsesBackFromItsName) {
  for (const TransferMode mode : {TransferMode::Paper, TransferMode::Informed, TransferMode::Prior,
                                  TransferMode::Seeded, TransferMode::Shaping, TransferMode::Ordered}) {
    EXPECT_EQ(parse_enum<TransferMode>(enum_name(mode)), mode);
    EXPECT_NE(std::string(enum_choices<TransferMode>()).find(enum_name(mode)), std::string::npos);
  }
  EXPECT_EQ(parse_enum<TransferMode>("Paper"), std::nullopt);
  EXPECT_EQ(parse_enum<TransferMode>(""), std::nullopt);
}

}  // namespace
}  // namespace crux
