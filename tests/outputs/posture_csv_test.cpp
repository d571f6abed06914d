#include "outputs/posture_csv.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(PostureCsv, NamesEveryJointAndReadsBackExactly) {
  const BodyModel& model = testing::human_model();
  Random random(5);
  const std::vector<Posture> postures{testing::random_posture(model, random), testing::random_posture(model, random)};
  const std::string csv = posture_csv(model, postures, "step");
  std::istringstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("step,", 0), 0u);
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), kConfigurationDof);
  for (std::size_t n = 0; n < postures.size(); ++n) {
    std::string line;
    std::getline(in, line);
    std::istringstream row(line);
    std::string cell;
    std::getline(row, cell, ',');
    EXPECT_EQ(cell, std::to_string(n));
    for (int i = 0; i < kConfigurationDof; ++i) {
      std::getline(row, cell, ',');
      EXPECT_EQ(std::stod(cell), postures[n][i]) << "joint " << i;
    }
  }
}

// Each value is the shortest text that reads back to it: 0.1, not 0.10000000000000001.
TEST(PostureCsv, ValuesAreTheShortestTextThatReadsBack) {
  const std::vector<Posture> postures{standing_posture(Eigen::Vector3d(0.1, 196.6, 1.0 / 3.0))};
  const std::string csv = posture_csv(testing::human_model(), postures, "step");
  const std::string row = csv.substr(csv.find('\n') + 1);
  EXPECT_EQ(row.rfind("0,0.1,196.6,0.3333333333333333,", 0), 0u) << row;
}

}  // namespace
}  // namespace crux
