#include "learning/q_table_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

const std::string kSpace = "a 5 x 7 test space";

QTable sample_table() {
  QTable q(35);
  q.set_value(186623, 34, -99.34165);
  q.set_value(7, 0, 200000.0);
  q.set_value(7, 12, -0.0);
  q.add_visit(7, 12);
  q.add_visit(7, 12);
  q.set_visits(42, 3, 4000000000u);
  return q;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(QTableFile, RoundTripIsExactAndDeterministic) {
  const auto path = testing::write_temporary("q_round_trip.bin", "");
  const QTable q = sample_table();
  save_q_table(path.string(), q, kSpace);
  const std::string first = read_bytes(path);
  const QTable loaded = load_q_table(path.string(), 35, kSpace);
  EXPECT_EQ(loaded.state_count(), q.state_count());
  q.for_each_row([&](StateCode s, std::span<const double> values, std::span<const std::uint32_t> visits) {
    for (int a = 0; a < 35; ++a) {
      EXPECT_EQ(loaded.value(s, a), values[a]);
      EXPECT_EQ(loaded.visits(s, a), visits[a]);
    }
  });
  EXPECT_TRUE(std::signbit(loaded.value(7, 12)));
  save_q_table(path.string(), loaded, kSpace);
  EXPECT_EQ(read_bytes(path), first) << "the same table gives the same bytes";
}

struct BadFile {
  const char* name;
  std::string (*make)(const std::string& good);
  const char* expected;
};

class BadQTableFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(BadQTableFile, IsOneClearErrorAndLeavesTheFileAlone) {
  const auto good_path = testing::write_temporary("q_good.bin", "");
  save_q_table(good_path.string(), sample_table(), kSpace);
  const std::string bad = GetParam().make(read_bytes(good_path));
  const auto path = testing::write_temporary(std::string("q_bad_") + GetParam().name + ".bin", bad);
  try {
    load_q_table(path.string(), 35, kSpace);
    FAIL() << "loaded a bad file";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path.string(), 0), 0u) << message;
    EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  EXPECT_EQ(read_bytes(path), bad) << "a failed load never rewrites the file";
}

std::string truncate_half(const std::string& g) { return g.substr(0, g.size() / 2); }
std::string truncate_header(const std::string& g) { return g.substr(0, 12); }
std::string drop_checksum(const std::string& g) { return g.substr(0, g.size() - 8); }
std::string foreign(const std::string&) { return "PK\x03\x04 this is a zip file, not a Q-table"; }
std::string wall_json(const std::string&) { return R"({"format": "crux-wall", "version": 1})"; }
std::string empty(const std::string&) { return ""; }
std::string future_version(const std::string& g) {
  std::string b = g;
  b[8] = 3;
  return b;
}
std::string first_version(const std::string& g) {
  std::string b = g;
  b[8] = 1;
  return b;
}
// The space's byte count (offset 16) claims more than the file holds.
std::string huge_space(const std::string& g) {
  std::string b = g;
  b[19] = 0x7f;
  return b;
}
std::string flip_a_value_bit(const std::string& g) {
  std::string b = g;
  b[b.size() - 20] ^= 0x10;  // inside the last row
  return b;
}
std::string extra_bytes(const std::string& g) { return g + "xx"; }

INSTANTIATE_TEST_SUITE_P(
    Cases, BadQTableFile,
    ::testing::Values(
        BadFile{"truncated", truncate_half, "truncated"}, BadFile{"header_only", truncate_header, "truncated"},
        BadFile{"no_checksum", drop_checksum, "truncated"}, BadFile{"foreign", foreign, "not a crux Q-table file"},
        BadFile{"wall_file", wall_json, "not a crux Q-table file"}, BadFile{"empty", empty, "empty"},
        BadFile{"wrong_version", future_version, "unsupported Q-table file version 3"},
        BadFile{"first_version", first_version, "does not record the state space"},
        BadFile{"huge_space", huge_space, "a state space name of"}, BadFile{"corrupted", flip_a_value_bit, "checksum"},
        BadFile{"trailing", extra_bytes, "trailing data"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(QTableFile, AnotherStateSpaceIsRefusedNamingBoth) {
  const auto path = testing::write_temporary("q_space.bin", "");
  save_q_table(path.string(), sample_table(), kSpace);
  try {
    load_q_table(path.string(), 35, "a 7 x 5 test space");
    FAIL() << "loaded a table of another space";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("learnt on a 5 x 7 test space, this run uses a 7 x 5 test space"),
              std::string::npos)
        << e.what();
  }
}

TEST(QTableFile, WrongActionCountMissingFileAndDirectory) {
  const auto path = testing::write_temporary("q_35.bin", "");
  save_q_table(path.string(), sample_table(), kSpace);
  EXPECT_THROW(load_q_table(path.string(), 40, kSpace), InputError);
  EXPECT_THROW(load_q_table("/nonexistent/q.bin", 35, kSpace), InputError);
  EXPECT_THROW(load_q_table(std::filesystem::temp_directory_path().string(), 35, kSpace), InputError);
  const auto single = testing::write_temporary("q_1.bin", "");
  save_q_table(single.string(), QTable(1), kSpace);
  try {
    load_q_table(single.string(), 35, kSpace);
    FAIL() << "loaded a table of 1 action for 35";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the table has 1 action where 35 are expected"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace crux
