#include "views/effort_plot.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <regex>
#include <stdexcept>

#include "support/svg_check.hpp"

namespace crux {
namespace {

// Two lines through one point per stance, the limit at 1, and a cross on the top edge for
// a stance no forces balance (a gap in its line).
TEST(EffortPlot, DrawsBothSeriesTheLimitAndTheUnbalancedStances) {
  const double none = std::numeric_limits<double>::infinity();
  const EffortAlongClimb efforts{"Effort along the climb: test", {0.1, 0.3, 0.2, 0.5}, {0.2, 0.9, none, 1.4}};
  const std::string svg = render_effort_plot(efforts);
  testing::check_well_formed(svg);
  EXPECT_EQ(testing::count_of(svg, "r=\"3\" fill"), 7) << "one disc per finite effort";
  EXPECT_EQ(testing::count_of(svg, "class=\"unbalanced\""), 2) << "one cross, two strokes";
  EXPECT_NE(svg.find("on the three left when the next limb lets go"), std::string::npos);
  EXPECT_NE(svg.find("<title>Effort along the climb: test</title>"), std::string::npos);
  // The y axis reaches past the largest effort (1.4 x 1.05).
  const std::regex tick(">1\\.5<");
  EXPECT_TRUE(std::regex_search(svg, tick)) << "a tick at 1.5";
  EXPECT_EQ(render_effort_plot(efforts), svg) << "deterministic";
  EXPECT_THROW(render_effort_plot({"x", {0.1}, {}}), std::invalid_argument);
  EXPECT_THROW(render_effort_plot({"x", {}, {}}), std::invalid_argument);
}

}  // namespace
}  // namespace crux
