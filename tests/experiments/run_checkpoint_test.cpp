#include "experiments/run_checkpoint.hpp"

#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(RunCheckpoint, TheFileGivesBackTheStateOfItsOwnRunOnly) {
  const std::string state("\0\1binary\xff", 10);
  const auto file =
      testing::write_temporary("checkpoint.bin", checkpoint_file_bytes("[experiment]\nseed = 5\n", state));
  EXPECT_EQ(read_checkpoint(file, "[experiment]\nseed = 5\n"), state);
  try {
    read_checkpoint(file, "[experiment]\nseed = 6\n");
    FAIL() << "another run's checkpoint was taken";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), file.string());
    EXPECT_NE(std::string(e.what()).find("other parameters"), std::string::npos);
  }
  EXPECT_EQ(read_checkpoint(file.string() + ".missing", "x"), std::nullopt);
}

TEST(RunCheckpoint, AForeignOrTruncatedFileIsRefused) {
  const std::string whole = checkpoint_file_bytes("identity", "state");
  const auto foreign = testing::write_temporary("foreign.bin", "PNG not a checkpoint");
  EXPECT_THROW(read_checkpoint(foreign, "identity"), InputError);
  const auto truncated = testing::write_temporary("truncated.bin", whole.substr(0, whole.size() - 2));
  EXPECT_THROW(read_checkpoint(truncated, "identity"), InputError);
  // Any flipped byte of the state is caught by the digest before the state is read.
  for (std::size_t at = whole.size() - 5; at < whole.size(); ++at) {
    std::string damaged = whole;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
    const auto file = testing::write_temporary("damaged.bin", damaged);
    try {
      read_checkpoint(file, "identity");
      FAIL() << "a flipped byte at " << at << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("damaged"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace crux
