#include "reports/posture_csv.hpp"

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

}  // namespace
}  // namespace crux
