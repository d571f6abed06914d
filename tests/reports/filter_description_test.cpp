#include "reports/filter_description.hpp"

#include <gtest/gtest.h>

#include "reports/paper_reference.hpp"

namespace crux {
namespace {

// Hand-made counts per reading; the selected reading's are the headline.
TEST(FilterDescription, TheSelectedReadingIsTheHeadlineBesideThePapers) {
  FilterReport report;
  report.wall_count = 2;
  report.wall_seed = 9;
  report.parameters.feet_above_hands = kFeetAboveHandsReadings[1];
  for (std::size_t r = 0; r < report.counts.size(); ++r) {
    report.counts[r].configurations3 = 1000;
    report.counts[r].pass3 = 100 + r;
    report.counts[r].configurations4 = 2000;
    report.counts[r].pass4 = 40 + r;
  }
  const auto json = filter_json(report);
  EXPECT_EQ(json["reading"], enum_name(kFeetAboveHandsReadings[1]));
  EXPECT_EQ(json["passing3"], 101);
  EXPECT_DOUBLE_EQ(json["pass4"].get<double>(), 41.0 / 2000.0);
  EXPECT_DOUBLE_EQ(json["paper_pass3"].get<double>(), kPaperFilterPass3);
  EXPECT_EQ(json["readings"].size(), kFeetAboveHandsReadings.size());
  const std::string text = filter_text(report);
  const std::size_t marked = text.find("  <- selected");
  ASSERT_NE(marked, std::string::npos);
  const std::size_t line = text.rfind('\n', marked) + 1;
  EXPECT_EQ(text.compare(line, std::string(enum_name(kFeetAboveHandsReadings[1])).size(),
                         enum_name(kFeetAboveHandsReadings[1])),
            0)
      << text;
  EXPECT_NE(text.find("selected: 101 of 1000 3-configurations and 41 of 2000 4-configurations pass\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.rfind("2 random walls (seed 9),", 0), 0u) << text;
  report.wall_count = 1;
  EXPECT_EQ(filter_text(report).rfind("1 random wall (seed 9),", 0), 0u);
}

}  // namespace
}  // namespace crux
