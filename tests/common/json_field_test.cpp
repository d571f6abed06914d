#include "common/json_field.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "common/input_error.hpp"

namespace crux {
namespace {

const std::string kJsonFile = "s.json";

// The problem of the InputError that `read` raises, naming kJsonFile.
std::string json_problem(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), kJsonFile);
    return e.problem();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

const OrderedJson kJsonDocument = OrderedJson::parse(R"({
  "name": "wall", "count": 3, "big": 3000000000, "ratio": 0.5, "on": true, "none": null,
  "runs": [{"lengths": [4, 2]}, {"lengths": []}]
})");

TEST(JsonField, ReadsValuesAndNamesTheirPath) {
  const JsonField root(kJsonFile, kJsonDocument);
  EXPECT_EQ(root["name"].string(), "wall");
  EXPECT_EQ(root["count"].integer(), 3);
  EXPECT_EQ(root["count"].integer(3, 3), 3);
  EXPECT_EQ(root["big"].unsigned_integer(), 3000000000u);
  EXPECT_DOUBLE_EQ(root["ratio"].number(), 0.5);
  EXPECT_DOUBLE_EQ(root["count"].number(), 3.0) << "an integer is a number";
  EXPECT_TRUE(root["on"].boolean());
  EXPECT_TRUE(root["none"].is_null());
  EXPECT_TRUE(root.contains("runs"));
  EXPECT_FALSE(root.contains("walls"));
  const JsonField lengths = root["runs"][0]["lengths"];
  EXPECT_EQ(lengths.path(), "runs[0].lengths");
  EXPECT_EQ(lengths.size(), 2u);
  EXPECT_EQ(lengths[1].integer(), 2);
  EXPECT_EQ(lengths[1].path(), "runs[0].lengths[1]");
  EXPECT_EQ(json_child_path("", "name"), "name");
  EXPECT_EQ(json_child_path("holds[3]", "radius"), "holds[3].radius");
}

TEST(JsonField, AMissingKeyIsNamedWithItsPath) {
  const JsonField root(kJsonFile, kJsonDocument);
  EXPECT_EQ(json_problem([&] { root["walls"]; }), "walls is missing");
  EXPECT_EQ(json_problem([&] { root["runs"][1]["wall_pair"]; }), "runs[1].wall_pair is missing");
}

TEST(JsonField, AValueOfTheWrongTypeIsNamedWithWhatItIs) {
  const JsonField root(kJsonFile, kJsonDocument);
  EXPECT_EQ(json_problem([&] { root["name"].number(); }), "name must be a number, got string");
  EXPECT_EQ(json_problem([&] { root["ratio"].integer(); }),
            "ratio must be an integer from -2147483648 to 2147483647, got 0.5");
  EXPECT_EQ(json_problem([&] { root["count"].string(); }), "count must be a string, got 3");
  EXPECT_EQ(json_problem([&] { root["none"].boolean(); }), "none must be true or false, got null");
  EXPECT_EQ(json_problem([&] { root["on"].size(); }), "on must be an array, got true");
  EXPECT_EQ(json_problem([&] { root["name"]["x"]; }), "name must be an object, got string");
  EXPECT_EQ(json_problem([&] { JsonField(kJsonFile, OrderedJson::array())["x"]; }),
            "the top level must be an object, got array");
}

TEST(JsonField, AValueOutOfRangeIsRefused) {
  const JsonField root(kJsonFile, kJsonDocument);
  EXPECT_EQ(json_problem([&] { root["count"].integer(4); }), "count must be an integer from 4 to 2147483647, got 3");
  EXPECT_EQ(json_problem([&] { root["count"].integer(0, 2); }), "count must be an integer from 0 to 2, got 3");
  EXPECT_EQ(json_problem([&] { root["big"].integer(); }),
            "big must be an integer from -2147483648 to 2147483647, got 3000000000");
  EXPECT_EQ(json_problem([&] { root["runs"][2]; }), "runs has 2 values; there is no [2]");
  EXPECT_EQ(json_problem([&] { root["ratio"].unsigned_integer(); }),
            "ratio must be an integer from 0 to 18446744073709551615, got 0.5");
  EXPECT_EQ(
      json_problem([&] { JsonField(kJsonFile, OrderedJson::parse("{\"seed\": -1}"))["seed"].unsigned_integer(); }),
      "seed must be an integer from 0 to 18446744073709551615, got -1");
  EXPECT_EQ(json_problem([&] { root["runs"][0]["lengths"].expect_size(3); }), "runs[0].lengths has 2 values, not 3");
}

}  // namespace
}  // namespace crux
