#include "learning/transfer_mode.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(TransferMode, EveryModeParsesBackFromItsName) {
  for (const TransferMode mode : {TransferMode::Paper, TransferMode::Informed, TransferMode::Prior,
                                  TransferMode::Seeded, TransferMode::Shaping, TransferMode::Ordered}) {
    EXPECT_EQ(parse_transfer_mode(transfer_mode_name(mode)), mode);
    EXPECT_NE(std::string(transfer_mode_names()).find(transfer_mode_name(mode)), std::string::npos);
  }
  EXPECT_EQ(parse_transfer_mode("Paper"), std::nullopt);
  EXPECT_EQ(parse_transfer_mode(""), std::nullopt);
}

}  // namespace
}  // namespace crux
