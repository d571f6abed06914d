#include "common/sha256.hpp"

#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

// FIPS 180-2's published examples.
TEST(Sha256, MatchesThePublishedDigests) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, OfAFileIsOfItsBytesAndAMissingFileIsAnInputError) {
  const auto path = testing::write_temporary("sha256.txt", "abc");
  EXPECT_EQ(sha256_of_file(path.string(), "test file"), sha256_hex("abc"));
  EXPECT_THROW(sha256_of_file("/nonexistent/file", "test file"), InputError);
}

}  // namespace
}  // namespace crux
