#include "wall/wall_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "support/same_bits.hpp"
#include "support/test_models.hpp"
#include "wall/random_wall.hpp"

namespace crux {
namespace {

using testing::replaced;
using testing::write_temporary;

std::string example_wall_path(const std::string& file_name) { return CRUX_SOURCE_DIR "/walls/" + file_name; }

using testing::same_bits;

void expect_identical(const Wall& expected, const Wall& actual) {
  EXPECT_EQ(expected.name, actual.name);
  EXPECT_TRUE(same_bits(expected.finish_height, actual.finish_height));
  EXPECT_EQ(expected.start, actual.start);
  ASSERT_EQ(expected.hold_count(), actual.hold_count());
  for (int i = 0; i < expected.hold_count(); ++i) {
    EXPECT_EQ(expected.holds[i].id, actual.holds[i].id) << "hold index " << i;
    EXPECT_TRUE(same_bits(expected.holds[i].radius, actual.holds[i].radius)) << "hold index " << i;
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_TRUE(same_bits(expected.holds[i].position[axis], actual.holds[i].position[axis]))
          << "hold index " << i << " axis " << axis << ": " << expected.holds[i].position[axis] << " vs "
          << actual.holds[i].position[axis];
    }
  }
}

TEST(WallFile, RandomWallsRoundTripBitForBit) {
  for (std::uint64_t seed : {1u, 2u, 42u, 2009u}) {
    const Wall wall = generate_random_wall(seed);
    const std::string text = wall_to_json(wall);
    expect_identical(wall, parse_wall(text, "round trip"));
    EXPECT_EQ(text, wall_to_json(parse_wall(text, "round trip"))) << "the text is a fixed point";
  }
}

TEST(WallFile, SaveThenLoadThroughAFileIsIdentical) {
  const Wall wall = generate_random_wall(7);
  const auto path = testing::test_folder() / "saved_wall.json";
  std::filesystem::create_directories(path.parent_path());
  save_wall(path.string(), wall);
  expect_identical(wall, load_wall(path.string()));
}

TEST(WallFile, AwkwardDoublesRoundTripExactly) {
  Wall wall = generate_random_wall(3);
  wall.name = "awkward \"numbers\"\n\ttab";
  wall.finish_height = 0.1 + 0.2;
  wall.holds[0].position = {-0.0, std::numeric_limits<double>::denorm_min(), 1e-300};
  wall.holds[1].position = {std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(), M_PI};
  wall.holds[2].position = {1.0 / 3.0, 123456789.123456789, -2.0};
  wall.holds[3].radius = std::nextafter(0.04, 1.0);
  expect_identical(wall, parse_wall(wall_to_json(wall), "awkward"));
}

TEST(WallFile, OutputIsPrettyWithOneHoldPerLine) {
  const Wall wall = generate_random_wall(1);
  const std::string text = wall_to_json(wall);
  EXPECT_EQ(text.rfind("{\n  \"format\": \"crux-wall\",\n  \"version\": 1,\n", 0), 0u) << text;
  EXPECT_NE(text.find("\"start\": {\"right_hand\": 17, \"left_hand\": 19, \"right_foot\": 2, \"left_foot\": 4}"),
            std::string::npos);
  EXPECT_NE(text.find("\n    {\"id\": 45, \"position\": [0.0, "), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 9 + wall.hold_count());
}

TEST(WallFile, HoldOrderIsTheFileOrderAndStartBecomesIndices) {
  const Wall wall = parse_wall(R"({"format": "crux-wall", "version": 1, "name": "unsorted", "finish_height": 3,
    "start": {"right_hand": 30, "left_hand": 10, "right_foot": 7, "left_foot": 2},
    "holds": [{"id": 10, "position": [0, 1, 2], "radius": 0.04}, {"id": 2, "position": [0, 1, 0], "radius": 0.04},
              {"id": 30, "position": [0, 0, 2], "radius": 0.05}, {"id": 7, "position": [0, 0, 0], "radius": 0.04}]})",
                               "unsorted");
  ASSERT_EQ(wall.hold_count(), 4);
  EXPECT_EQ(wall.holds[0].id, 10);
  EXPECT_EQ(wall.holds[3].id, 7);
  EXPECT_EQ(wall.start, (std::array<int, kLimbCount>{2, 0, 3, 1}));
  EXPECT_EQ(wall.finish_height, 3.0);
  EXPECT_EQ(wall.holds[2].radius, 0.05);
}

TEST(WallFile, HoldsOffTheWallPlaneAreAccepted) {
  Wall wall = generate_random_wall(5);
  wall.holds[10].position.x() = 0.12;
  EXPECT_EQ(parse_wall(wall_to_json(wall), "volume").holds[10].position.x(), 0.12);
}

struct ExampleWall {
  const char* file_name;
  int hold_count;
};

void PrintTo(const ExampleWall& wall, std::ostream* out) { *out << wall.file_name; }

class WallFileExample : public ::testing::TestWithParam<ExampleWall> {};

TEST_P(WallFileExample, LoadsWithAPlausibleStart) {
  const Wall wall = load_wall(example_wall_path(GetParam().file_name));
  ASSERT_EQ(wall.hold_count(), GetParam().hold_count);
  const auto at = [&](Limb limb) { return wall.holds[wall.start[static_cast<int>(limb)]].position; };
  // A 1.70 m climber standing on two low holds, hands above the shoulders, uncrossed.
  EXPECT_LT(at(Limb::RightHand).y(), at(Limb::LeftHand).y());
  EXPECT_LT(at(Limb::RightFoot).y(), at(Limb::LeftFoot).y());
  const double feet_apart = (at(Limb::LeftFoot) - at(Limb::RightFoot)).norm();
  EXPECT_GE(feet_apart, 0.5);
  EXPECT_LE(feet_apart, 0.7);
  const double hands_above_feet =
      (at(Limb::RightHand).z() + at(Limb::LeftHand).z()) / 2 - (at(Limb::RightFoot).z() + at(Limb::LeftFoot).z()) / 2;
  EXPECT_NEAR(hands_above_feet, 1.5, 0.15);
  double lowest_hold = wall.holds[0].position.z();
  for (const Hold& hold : wall.holds) lowest_hold = std::min(lowest_hold, hold.position.z());
  EXPECT_LT(at(Limb::RightFoot).z() - lowest_hold, 0.35) << "the feet start near the bottom";
  EXPECT_GT(wall.finish_height, at(Limb::RightFoot).z() + 1.0) << "reaching the finish takes climbing";
}

INSTANTIATE_TEST_SUITE_P(WallFile, WallFileExample,
                         ::testing::Values(ExampleWall{"home_12.json", 12}, ExampleWall{"board_140.json", 140},
                                           ExampleWall{"tall_400.json", 400}),
                         [](const auto& info) { return "holds_" + std::to_string(info.param.hold_count); });

TEST(WallFile, SyntaxErrorReportsItsLineAndColumn) {
  const std::string text = "{\n  \"format\": \"crux-wall\",\n  \"version\": 1,,\n  \"name\": \"x\"\n}\n";
  // Line 3 is `  "version": 1,,`; its second comma, the 16th character, is the error.
  const auto path = write_temporary("syntax_line.json", text);
  try {
    load_wall(path.string());
    FAIL() << "loaded a file with a syntax error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("JSON syntax error at line 3, column 16: "), std::string::npos) << e.what();
  }
}

// Found by the wall fuzzer: a long unquoted token once overflowed the stack in the
// regular expression that reworded the parser's message.
TEST(WallFile, ALongInvalidTokenIsOneShortLine) {
  // An unterminated string: the parser quotes all 50000 characters it read.
  const std::string text = "{\"format\": \"crux-wall\", \"name\": \"" + std::string(50000, 'D') + "\x01\"}";
  try {
    parse_wall(text, "long_token.json");
    FAIL() << "parsed an invalid token";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("JSON syntax error at line 1, column "), std::string::npos) << message.substr(0, 300);
    EXPECT_LT(message.size(), 400u);
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
  // A number too large for a double, 50000 digits long, is quoted short too.
  try {
    parse_wall("{\"finish_height\": 1" + std::string(50000, '2') + "}", "long_number.json");
    FAIL() << "parsed an overflowing number";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not finite"), std::string::npos);
    EXPECT_LT(std::string(e.what()).size(), 400u);
  }
}

TEST(WallFile, SavingAWallThatCouldNotLoadBackWritesNothing) {
  Wall wall = generate_random_wall(1);
  wall.holds[4].position.z() = std::numeric_limits<double>::quiet_NaN();
  const auto path = testing::test_folder() / "never_written.json";
  std::filesystem::remove(path);
  try {
    save_wall(path.string(), wall);
    FAIL() << "saved a wall with a NaN coordinate";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("not written"), std::string::npos) << message;
    EXPECT_NE(message.find("holds[4].position[2]"), std::string::npos) << message;
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(WallFile, UnreadableFileIsAnInputError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root reads every file";
  const auto path = write_temporary("unreadable.json", "{}");
  std::filesystem::permissions(path, std::filesystem::perms::none);
  try {
    load_wall(path.string());
    FAIL() << "read an unreadable file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot read the file"), std::string::npos) << e.what();
  }
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
}

// Every bad input is one InputError that names the file and the problem on one line.
enum class BadPath { WrittenFile, Directory, Missing };

struct BadWallCase {
  const char* name;
  std::string text;
  const char* expected_problem;
  BadPath kind = BadPath::WrittenFile;
};

// Five holds; the start is 3, 4 (hands) and 1, 2 (feet).
constexpr const char* kValidWall = R"({
  "format": "crux-wall",
  "version": 1,
  "name": "test wall",
  "finish_height": 2.5,
  "start": {"right_hand": 3, "left_hand": 4, "right_foot": 1, "left_foot": 2},
  "holds": [
    {"id": 1, "position": [0.0, 0.3, 0.0], "radius": 0.04},
    {"id": 2, "position": [0.0, 0.9, 0.0], "radius": 0.04},
    {"id": 3, "position": [0.0, 0.3, 1.5], "radius": 0.04},
    {"id": 4, "position": [0.0, 0.9, 1.5], "radius": 0.04},
    {"id": 5, "position": [0.0, 0.6, 2.0], "radius": 0.04}
  ]
}
)";

BadWallCase edit(const char* name, const std::string& from, const std::string& to, const char* expected) {
  return {name, replaced(kValidWall, from, to), expected};
}
// The same edit of the valid wall written as version 2.
BadWallCase edit_v2(const char* name, const std::string& from, const std::string& to, const char* expected) {
  return {name, replaced(replaced(kValidWall, "\"version\": 1", "\"version\": 2"), from, to), expected};
}
BadWallCase whole(const char* name, const std::string& text, const char* expected) { return {name, text, expected}; }

// One hold more than crux supports, each on its own spot.
std::string too_many_holds() {
  std::string holds;
  for (int id = 1; id <= kMaxHoldCount + 1; ++id) {
    holds += fmt::format(R"({}{{"id": {}, "position": [0, {}, {}], "radius": 0.04}})", id > 1 ? ", " : "", id, id % 100,
                         id / 100);
  }
  return R"({"format": "crux-wall", "version": 1, "name": "n", "finish_height": 1, "start": {}, "holds": [)" + holds +
         "]}";
}

const std::string kHold3 = R"({"id": 3, "position": [0.0, 0.3, 1.5], "radius": 0.04})";

std::vector<BadWallCase> bad_wall_cases() {
  return {
      {"directory", "", "is a directory, not a wall file", BadPath::Directory},
      {"missing_file", "", "no such file", BadPath::Missing},
      whole("empty", "", "the file is empty"),
      whole("only_whitespace", " \n\t\n", "the file is empty"),
      edit("syntax_error", "\"version\": 1,", "\"version\": 1,,", "JSON syntax error at line 3, column 16"),
      edit("truncated", "  ]\n}", "  ]", "JSON syntax error at line 14"),
      edit("nan_literal", "0.3, 1.5]", "NaN, 1.5]", "JSON syntax error at line 10"),
      edit("trailing_garbage", "  ]\n}\n", "  ]\n}\n}", "JSON syntax error at line 15, column 1"),
      // The JSON parser stops at a NUL byte: what follows it must not be ignored.
      edit("nul_byte", "  ]\n}\n", std::string("  ]\n}\n\0{\"holds\": []}\n", 21), "a NUL byte at offset 487"),
      whole("not_an_object", "[1, 2, 3]", "the top level must be a JSON object, got array"),
      edit("format_missing", "\"format\": \"crux-wall\",", "", "format is missing"),
      edit("format_wrong", "\"crux-wall\"", "\"crux-body\"", "format must be \"crux-wall\", got \"crux-body\""),
      edit("format_not_string", "\"crux-wall\"", "1", "format must be \"crux-wall\", got 1"),
      edit("version_missing", "\"version\": 1,", "", "version is missing (supported versions: 1, 2)"),
      edit("version_unsupported", "\"version\": 1", "\"version\": 3",
           "version 3 is not supported (supported versions: 1, 2)"),
      // Version 2 (issue 26): an incline and support directions, refused in version 1.
      edit("incline_in_version_1", "\"finish_height\"", "\"incline\": 40, \"finish_height\"",
           "unknown key \"incline\" at the top level (allowed: format, version, name, finish_height, start, holds); "
           "it needs \"version\": 2"),
      edit("support_in_version_1", "1.5], \"radius\": 0.04", "1.5], \"radius\": 0.04, \"support\": [0, 0, 1]",
           "it needs \"version\": 2"),
      edit_v2("incline_vertical_overhang", "\"finish_height\"", "\"incline\": 90, \"finish_height\"",
              "incline is 90 degrees; it must be between -90 and 90 (exclusive)"),
      edit_v2("incline_string", "\"finish_height\"", "\"incline\": \"steep\", \"finish_height\"",
              "incline must be a number, got string"),
      edit_v2("support_zero", "1.5], \"radius\": 0.04", "1.5], \"radius\": 0.04, \"support\": [0, 0, 0]",
              "holds[2].support must be a direction [x, y, z] of non-zero length, got [0,0,0]"),
      edit_v2("support_two_numbers", "1.5], \"radius\": 0.04", "1.5], \"radius\": 0.04, \"support\": [0, 1]",
              "holds[2].support must have 3 coordinates [x, y, z], got 2"),
      edit_v2("support_not_array", "1.5], \"radius\": 0.04", "1.5], \"radius\": 0.04, \"support\": \"up\"",
              "holds[2].support must be an array of 3 numbers [x, y, z], got string"),
      edit("version_string", "\"version\": 1", "\"version\": \"1\"", "version must be an integer, got string"),
      edit("unknown_top_level_key", "\"finish_height\"", "\"finsh_height\"",
           "unknown key \"finsh_height\" at the top level"),
      edit("unknown_hold_key", "\"radius\": 0.04}", "\"radius\": 0.04, \"colour\": \"red\"}",
           "unknown key \"colour\" in holds[0] (allowed: id, position, radius)"),
      edit("unknown_start_key", "\"left_foot\": 2}", "\"left_foot\": 2, \"tail\": 5}", "unknown key \"tail\" in start"),
      edit("unknown_key_with_newline", "\"finish_height\"", "\"finish\\nheight\"", "unknown key \"finish\\nheight\""),
      edit("duplicate_key", "\"radius\": 0.04}", "\"radius\": 0.04, \"radius\": 0.05}",
           "duplicate key \"radius\" in holds[0]"),
      edit("duplicate_top_level_key", "\"version\": 1,", "\"version\": 1, \"version\": 1,",
           "duplicate key \"version\" at the top level"),
      edit("name_missing", "\"name\": \"test wall\",", "", "name is missing"),
      edit("name_not_string", "\"test wall\"", "7", "name must be a string, got 7"),
      edit("finish_height_missing", "\"finish_height\": 2.5,", "", "finish_height is missing"),
      edit("finish_height_string", "2.5,", "\"2.5\",", "finish_height must be a number, got string"),
      edit("finish_height_infinite", "2.5,", "1e999,", "finish_height is not finite (1e999 overflows a double)"),
      whole("holds_missing", R"({"format": "crux-wall", "version": 1, "name": "n", "finish_height": 1, "start": {}})",
            "holds is missing"),
      whole("holds_not_array",
            replaced(replaced(kValidWall, "\"holds\": [", "\"holds\": {\"a\": ["), "  ]\n}", "  ]}\n}"),
            "holds must be an array, got object"),
      edit("hold_not_object", kHold3, "[3, 0.3, 1.5]", "holds[2] must be an object, got array"),
      whole("three_holds", R"({"format": "crux-wall", "version": 1, "name": "n", "finish_height": 1, "start": {},
              "holds": [{"id": 1, "position": [0, 0, 0], "radius": 0.04}, {"id": 2, "position": [0, 1, 0], "radius": 0.04},
                        {"id": 3, "position": [0, 0, 1], "radius": 0.04}]})",
            "holds has 3 entries; a wall needs at least 4 holds (one per limb)"),
      whole("one_hold", R"({"format": "crux-wall", "version": 1, "name": "n", "finish_height": 1, "start": {},
              "holds": [{"id": 1, "position": [0, 0, 0], "radius": 0.04}]})",
            "holds has 1 entry; a wall needs at least 4 holds (one per limb)"),
      whole("too_many_holds", too_many_holds(), "holds has 10001 entries; crux supports at most 10000 holds on a wall"),
      edit("radius_missing", kHold3, R"({"id": 3, "position": [0.0, 0.3, 1.5]})", "holds[2].radius is missing"),
      edit("position_missing", kHold3, R"({"id": 3, "radius": 0.04})", "holds[2].position is missing"),
      edit("id_missing", kHold3, R"({"position": [0.0, 0.3, 1.5], "radius": 0.04})", "holds[2].id is missing"),
      edit("duplicate_id", "\"id\": 5,", "\"id\": 2,", "duplicate hold id 2 (holds[1] and holds[4])"),
      edit("id_zero", "\"id\": 5,", "\"id\": 0,", "holds[4].id must be a positive integer, got 0"),
      edit("id_negative", "\"id\": 5,", "\"id\": -5,", "holds[4].id must be a positive integer, got -5"),
      edit("id_fractional", "\"id\": 5,", "\"id\": 5.5,", "holds[4].id must be a positive integer, got 5.5"),
      edit("id_float_integer", "\"id\": 5,", "\"id\": 5.0,", "holds[4].id must be a positive integer, got 5.0"),
      edit("id_string", "\"id\": 5,", "\"id\": \"5\",", "holds[4].id must be a positive integer, got string"),
      edit("id_too_large", "\"id\": 5,", "\"id\": 4294967296,", "larger than the largest supported hold id 2147483647"),
      edit("position_two_numbers", "[0.0, 0.3, 1.5]", "[0.3, 1.5]",
           "holds[2].position must have 3 coordinates [x, y, z], got 2"),
      edit("position_four_numbers", "[0.0, 0.3, 1.5]", "[0.0, 0.3, 1.5, 1.0]",
           "holds[2].position must have 3 coordinates"),
      edit("position_not_array", "[0.0, 0.3, 1.5]", "\"0 0.3 1.5\"",
           "holds[2].position must be an array of 3 numbers [x, y, z], got string"),
      edit("position_string_coordinate", "[0.0, 0.3, 1.5]", "[0.0, 0.3, \"1.5\"]",
           "holds[2].position[2] must be a number, got string"),
      edit("position_null_coordinate", "[0.0, 0.3, 1.5]", "[0.0, null, 1.5]",
           "holds[2].position[1] must be a number, got null"),
      edit("position_infinite", "[0.0, 0.3, 1.5]", "[0.0, 1e999, 1.5]", "holds[2].position[1] is not finite"),
      edit("position_minus_infinite", "[0.0, 0.3, 1.5]", "[-1e400, 0.3, 1.5]", "holds[2].position[0] is not finite"),
      edit("radius_zero", "1.5], \"radius\": 0.04", "1.5], \"radius\": 0", "holds[2].radius must be positive, got 0"),
      edit("radius_negative", "1.5], \"radius\": 0.04", "1.5], \"radius\": -0.01",
           "holds[2].radius must be positive, got -0.01"),
      edit("radius_infinite", "1.5], \"radius\": 0.04", "1.5], \"radius\": 1e999", "holds[2].radius is not finite"),
      edit("radius_string", "1.5], \"radius\": 0.04", "1.5], \"radius\": \"big\"",
           "holds[2].radius must be a number, got string"),
      edit("start_missing",
           "  \"start\": {\"right_hand\": 3, \"left_hand\": 4, \"right_foot\": 1, \"left_foot\": 2},\n", "",
           "start is missing"),
      edit("start_not_object", "{\"right_hand\": 3, \"left_hand\": 4, \"right_foot\": 1, \"left_foot\": 2}",
           "[3, 4, 1, 2]", "start must be an object, got array"),
      edit("start_limb_missing", ", \"left_foot\": 2}", "}", "start.left_foot is missing"),
      edit("start_unknown_hold", "\"right_hand\": 3", "\"right_hand\": 99",
           "start.right_hand names hold 99, which is not in holds"),
      edit("start_same_hold_twice", "\"left_foot\": 2", "\"left_foot\": 3",
           "start.right_hand and start.left_foot both name hold 3; each limb needs its own hold"),
      edit("start_id_not_integer", "\"right_foot\": 1", "\"right_foot\": true",
           "start.right_foot must be a positive integer, got true"),
  };
}

void PrintTo(const BadWallCase& c, std::ostream* out) { *out << c.name; }

// Issue 26: version 2 carries an incline and support directions (normalised when read)
// and writes them back; a wall without either is written as version 1, byte for byte
// the file it was read from.
TEST(WallFile, VersionTwoCarriesTheInclineAndSupportDirections) {
  Wall wall = parse_wall(kValidWall, "valid.json");
  EXPECT_EQ(wall_to_json(wall), kValidWall) << "no incline, no support: version 1, as read";
  EXPECT_EQ(wall.incline_deg, 0.0);
  const std::string v2 = replaced(replaced(replaced(kValidWall, "\"version\": 1", "\"version\": 2"),
                                           "\"finish_height\"", "\"incline\": 40, \"finish_height\""),
                                  "1.5], \"radius\": 0.04", "1.5], \"radius\": 0.04, \"support\": [0, 0, 2]");
  wall = parse_wall(v2, "v2.json");
  EXPECT_EQ(wall.incline_deg, 40.0);
  ASSERT_TRUE(wall.holds[2].support.has_value());
  EXPECT_EQ(*wall.holds[2].support, Eigen::Vector3d(0, 0, 1));
  EXPECT_FALSE(wall.holds[0].support.has_value());
  const std::string written = wall_to_json(wall);
  EXPECT_NE(written.find("\"version\": 2"), std::string::npos);
  EXPECT_NE(written.find("\"incline\": 40.0"), std::string::npos) << written;
  EXPECT_NE(written.find("\"support\": [0.0, 0.0, 1.0]"), std::string::npos) << written;
  const Wall again = parse_wall(written, "again.json");
  EXPECT_EQ(wall_to_json(again), written);
  EXPECT_EQ(again.incline_deg, 40.0);
}

std::filesystem::path path_for(const BadWallCase& c) {
  const auto directory = testing::test_folder();
  switch (c.kind) {
    case BadPath::Directory:
      std::filesystem::create_directories(directory);
      return directory;
    case BadPath::Missing:
      return directory / "no_such_wall.json";
    case BadPath::WrittenFile:
      break;
  }
  return write_temporary(std::string("bad_wall_") + c.name + ".json", c.text);
}

class WallFileBadInput : public ::testing::TestWithParam<BadWallCase> {};

TEST_P(WallFileBadInput, IsOneClearInputError) {
  const BadWallCase& c = GetParam();
  const auto path = path_for(c);
  try {
    load_wall(path.string());
    FAIL() << "loaded a bad wall: " << c.name;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.source(), path.string());
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.expected_problem), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

INSTANTIATE_TEST_SUITE_P(WallFile, WallFileBadInput, ::testing::ValuesIn(bad_wall_cases()),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace crux
