#include "reports/sweep_description.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

TEST(SweepDescription, EachCellWithItsParametersAndEachMetricsDifference) {
  const auto summary = nlohmann::json::parse(R"({
    "listed_keys": ["learning.epsilon"],
    "cells": [{"cell": 0, "parameters": {"learning.epsilon": "0.1"}, "wall_pairs": 6, "seeds_per_wall": 3,
               "transfer_vs_control": {"jumpstart": {"transfer_minus_control":
                 {"mean": -12.5, "ci95_t_over_walls": [-20.25, -4.75], "p_value": 0.0125,
                  "p_value_holm_over_cells": 0.025}}}}]})");
  const std::string text = sweep_text(summary, "out/sweep", 40, 10, 2.5);
  EXPECT_NE(text.find("crux sweep: 1 cell (learning.epsilon)"), std::string::npos) << text;
  EXPECT_NE(text.find("cell 0 (learning.epsilon = 0.1): 6 walls x 3 seeds"), std::string::npos) << text;
  EXPECT_NE(text.find("jumpstart"), std::string::npos);
  EXPECT_NE(text.find("-12.5 [-20.25, -4.75]  p = 0.0125 (0.025)"), std::string::npos) << text;
  EXPECT_NE(text.find("wrote out/sweep (2.5 s; 10 of 40 tasks kept from an earlier start)"), std::string::npos);
}

TEST(SweepDescription, CountsOfOneAreSingular) {
  const auto summary = nlohmann::json::parse(R"({
    "listed_keys": [],
    "cells": [{"cell": 0, "parameters": {}, "wall_pairs": 1, "seeds_per_wall": 1, "transfer_vs_control": {}}]})");
  const std::string text = sweep_text(summary, "out/sweep", 1, 0, 2.5);
  EXPECT_EQ(text.rfind("crux sweep: 1 cell\n", 0), 0u) << text;
  EXPECT_NE(text.find("\ncell 0: 1 wall x 1 seed\n"), std::string::npos) << text;
  EXPECT_NE(text.find("wrote out/sweep (2.5 s; 0 of 1 task kept from an earlier start)"), std::string::npos) << text;
}

}  // namespace
}  // namespace crux
