#include "reports/sweep_report.hpp"

#include <gtest/gtest.h>

namespace crux {
namespace {

const char* kSummary = R"({
  "listed_keys": ["experiment.transfer"],
  "cells": [
    {"cell": 0, "parameters": {"experiment.transfer": "paper"},
     "transfer_vs_control": {"jumpstart": {"description": "length of the <first> episode",
       "transfer_minus_control": {"mean": -110.5, "ci95_t_over_walls": [-264.25, 43.0], "p_value": 0.1517,
                                  "p_value_holm_over_cells": 0.3034},
       "iqm": {"difference": {"value": -95.25, "low": -180.0, "high": null}},
       "probability_of_improvement": {"value": 0.625, "low": 0.5, "high": 0.75}}}},
    {"cell": 1, "parameters": {"experiment.transfer": "prior"},
     "transfer_vs_control": {"jumpstart": {"description": "length of the <first> episode",
       "transfer_minus_control": {"mean": 12.0, "ci95_t_over_walls": null, "p_value": 1.0,
                                  "p_value_holm_over_cells": 1.0}}}}]})";

TEST(SweepReport, ACellIsTitledByItsListedValues) {
  const auto summary = nlohmann::ordered_json::parse(kSummary);
  EXPECT_EQ(sweep_cell_title(summary["cells"][1]), "cell 1: experiment.transfer = prior");
  EXPECT_EQ(sweep_cell_title(nlohmann::ordered_json::parse(R"({"cell": 0, "parameters": {}})")), "cell 0");
}

TEST(SweepReport, ThePageTabulatesEachCellAndEmbedsTheFiguresInOrder) {
  const auto summary = nlohmann::ordered_json::parse(kSummary);
  const std::string html =
      sweep_report_html(summary, {"<?xml version=\"1.0\"?>\n<svg id=\"first\"></svg>", "<svg id=\"second\"></svg>"});
  EXPECT_NE(html.find("-110.5 [-264.2, +43]<br>p = 0.152 (Holm 0.303)"), std::string::npos) << html;
  EXPECT_NE(html.find("+12<br>p = 1 (Holm 1)"), std::string::npos) << "no interval: the mean and p only";
  // rliable's table follows the first: cell 0's IQM difference and P, cell 1 (a summary
  // without them) blank.
  const std::size_t rliable = html.find("<td>-95.25 [-180, -]<br>P 0.62 [0.50, 0.75]</td>");
  EXPECT_NE(rliable, std::string::npos) << html;
  EXPECT_LT(html.find("(Holm 0.303)"), rliable);
  EXPECT_NE(html.find("<td>cell 1: experiment.transfer = prior</td><td></td></tr>"), std::string::npos) << html;
  EXPECT_NE(html.find("length of the &lt;first&gt; episode"), std::string::npos) << "descriptions are escaped";
  EXPECT_NE(html.find("2 cells over experiment.transfer."), std::string::npos) << html;
  EXPECT_EQ(html.find("<?xml"), std::string::npos) << "an SVG's XML declaration is dropped inside HTML";
  const std::size_t first = html.find("<svg id=\"first\">"), second = html.find("<svg id=\"second\">");
  ASSERT_NE(first, std::string::npos);
  ASSERT_NE(second, std::string::npos);
  EXPECT_LT(first, second);
  EXPECT_LT(html.find("cell 0: experiment.transfer = paper"), html.find("cell 1: experiment.transfer = prior"));
}

TEST(SweepReport, OneCellIsSingular) {
  auto summary = nlohmann::ordered_json::parse(kSummary);
  summary["cells"].erase(1);
  EXPECT_NE(sweep_report_html(summary, {"<svg></svg>"}).find("<p>1 cell over experiment.transfer."), std::string::npos);
}

}  // namespace
}  // namespace crux
