#include "outputs/trajectory_csv.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "support/test_models.hpp"

namespace crux {
namespace {

std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream row(line);
  for (std::string cell; std::getline(row, cell, ',');) out.push_back(cell);
  return out;
}

TEST(TrajectoryCsv, EachSampleIsARowOfTimeMoveRotationForcesAndJoints) {
  const BodyModel& model = testing::human_model();
  TrajectorySample sample;
  sample.time = 0.25;
  sample.move = 3;
  sample.root_orientation = Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5);
  sample.hold_forces[static_cast<int>(Limb::LeftFoot)] = Eigen::Vector3d(1.5, -2.0, 300.125);
  sample.posture[kRootDof] = 0.1;
  const std::vector<TrajectorySample> samples{TrajectorySample{}, sample};
  std::istringstream in(trajectory_csv(model, samples));
  std::string header, first, second;
  std::getline(in, header);
  std::getline(in, first);
  std::getline(in, second);
  const std::vector<std::string> names = csv_cells(header);
  ASSERT_EQ(names.size(), 1u + 6u + 12u + kConfigurationDof);
  EXPECT_EQ(std::vector<std::string>(names.begin(), names.begin() + 7),
            (std::vector<std::string>{"sample", "time_s", "move", "root_qw", "root_qx", "root_qy", "root_qz"}));
  EXPECT_EQ(names[7], "right_hand_fx_n");
  EXPECT_EQ(names[18], "left_foot_fz_n");
  EXPECT_EQ(names[19], model.joints[0].name);
  const std::vector<std::string> row = csv_cells(second);
  ASSERT_EQ(row.size(), names.size());
  EXPECT_EQ(row[0], "1");
  EXPECT_EQ(row[1], "0.25");
  EXPECT_EQ(row[2], "3");
  EXPECT_EQ(std::vector<std::string>(row.begin() + 3, row.begin() + 7),
            (std::vector<std::string>{"0.5", "0.5", "-0.5", "0.5"}));
  EXPECT_EQ(std::vector<std::string>(row.begin() + 16, row.begin() + 19),
            (std::vector<std::string>{"1.5", "-2", "300.125"}));
  EXPECT_EQ(row[19 + kRootDof], "0.1");
  EXPECT_EQ(csv_cells(first)[2], "-1") << "a default sample belongs to the start";
}

}  // namespace
}  // namespace crux
