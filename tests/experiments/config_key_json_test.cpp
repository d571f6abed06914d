#include "experiments/config_key_json.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace crux {
namespace {

nlohmann::ordered_json declared(const ExperimentConfig& config, const std::string& key) {
  const auto fields = config_fields(config);
  const auto field = std::find_if(fields.begin(), fields.end(), [&](const auto& f) { return f.key == key; });
  return config_key_json(*field);
}

TEST(ConfigKeyJson, ANumberKeyGivesItsValueUnitAndBounds) {
  ExperimentConfig config;
  config.settings.learning.climbing.physics.friction = 0.7;
  const auto json = declared(config, "physics.friction");
  EXPECT_EQ(json["flag"], "--physics-friction");
  EXPECT_EQ(json["type"], "number");
  EXPECT_EQ(json["value"], 0.7);
  EXPECT_EQ(json["min"], 0.0);
  EXPECT_EQ(json["max"], 10.0);
  EXPECT_FALSE(json["min_open"]);
  EXPECT_FALSE(json["sizes_work"]);
  EXPECT_TRUE(json["choices"].is_null());
}

TEST(ConfigKeyJson, ACountThatSizesTheWorkSaysSo) {
  const auto json = declared(ExperimentConfig{}, "experiment.iterations");
  EXPECT_EQ(json["type"], "integer");
  EXPECT_EQ(json["value"], 8000);
  EXPECT_TRUE(json["sizes_work"]);
}

TEST(ConfigKeyJson, UnsetKeysAndUnboundedSidesAreNull) {
  const auto runs = declared(ExperimentConfig{}, "experiment.runs");
  EXPECT_TRUE(runs["value"].is_null());
  const auto seed = declared(ExperimentConfig{}, "experiment.seed");
  EXPECT_TRUE(seed["min"].is_null());
  EXPECT_TRUE(seed["max"].is_null());
}

TEST(ConfigKeyJson, AChoiceGivesItsNameAndTheChoices) {
  const auto json = declared(ExperimentConfig{}, "physics.model");
  EXPECT_EQ(json["type"], "choice");
  EXPECT_EQ(json["value"], "kinematic");
  EXPECT_EQ(json["choices"], "kinematic, static or dynamic");
}

}  // namespace
}  // namespace crux
