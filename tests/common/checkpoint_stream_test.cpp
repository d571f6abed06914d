#include "common/checkpoint_stream.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/input_error.hpp"

namespace crux {
namespace {

TEST(CheckpointStream, ValuesVectorsAndTextComeBackBitForBit) {
  CheckpointWriter out;
  out.value<std::uint64_t>(18446744073709551615ULL);
  out.value(-0.0);
  out.value(std::numeric_limits<double>::denorm_min());
  out.vector(std::vector<int>{3, -1, 7});
  out.vector(std::vector<double>{});
  out.text("a\nb");
  const std::string bytes = out.take();
  CheckpointReader in(bytes, "state.bin");
  EXPECT_EQ(in.value<std::uint64_t>(), 18446744073709551615ULL);
  const double negative_zero = in.value<double>();
  EXPECT_TRUE(negative_zero == 0.0 && std::signbit(negative_zero));
  EXPECT_EQ(in.value<double>(), std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(in.vector<int>(), (std::vector<int>{3, -1, 7}));
  EXPECT_TRUE(in.vector<double>().empty());
  EXPECT_EQ(in.text(), "a\nb");
  EXPECT_TRUE(in.at_end());
}

TEST(CheckpointStream, TruncatedBytesOrImpossibleCountsAreAnErrorNamingTheSource) {
  CheckpointWriter out;
  out.vector(std::vector<std::uint64_t>{1, 2, 3});
  const std::string bytes = out.take();
  for (std::size_t keep = 0; keep < bytes.size(); ++keep) {
    CheckpointReader in(std::string_view(bytes).substr(0, keep), "state.bin");
    try {
      in.vector<std::uint64_t>();
      FAIL() << "read " << keep << " of " << bytes.size() << " bytes";
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "state.bin");
    }
  }
  CheckpointWriter huge;
  huge.value<std::uint64_t>(std::numeric_limits<std::uint64_t>::max());
  const std::string count_only = huge.take();
  CheckpointReader in(count_only, "state.bin");
  EXPECT_THROW(in.vector<double>(), InputError) << "no allocation of 2^64 doubles";
}

}  // namespace
}  // namespace crux
