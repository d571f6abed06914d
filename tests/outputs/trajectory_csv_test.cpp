#include "outputs/trajectory_csv.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "common/input_error.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

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

fs::path trajectory_file(const std::string& name, const std::string& text) {
  return testing::write_temporary("trajectory_" + name, text);
}

TEST(TrajectoryCsv, ReadsBackWhatItWrote) {
  const BodyModel& model = testing::human_model();
  std::vector<TrajectorySample> samples(3);
  for (int i = 0; i < 3; ++i) {
    samples[i].time = 0.02 * i + 1.0 / 3.0;
    samples[i].move = i - 1;
    samples[i].root_orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * i, Eigen::Vector3d(1, 2, 3).normalized()));
    samples[i].hold_forces[i] = Eigen::Vector3d(1.0 / 7.0, -2.5, 300.0 + i);
    samples[i].posture = standing_posture(Eigen::Vector3d(-0.3, 0.5, 1.0));
    samples[i].posture[kRootDof + i] += 0.01 / 3.0;
  }
  const fs::path file = trajectory_file("round_trip.csv", trajectory_csv(model, samples));
  const std::vector<TrajectorySample> read = read_trajectory_csv(model, file);
  ASSERT_EQ(read.size(), samples.size());
  for (std::size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read[i].time, samples[i].time);
    EXPECT_EQ(read[i].move, samples[i].move);
    EXPECT_EQ(read[i].root_orientation.coeffs(), samples[i].root_orientation.coeffs());
    for (int limb = 0; limb < kLimbCount; ++limb) EXPECT_EQ(read[i].hold_forces[limb], samples[i].hold_forces[limb]);
    EXPECT_EQ(read[i].posture, samples[i].posture);
  }
}

// Each bad file is one InputError naming the file and the line.
TEST(TrajectoryCsv, ABadFileIsOneErrorNamingItsLine) {
  const BodyModel& model = testing::human_model();
  std::vector<TrajectorySample> samples(2);
  samples[1].time = 0.02;
  samples[1].move = 0;
  for (TrajectorySample& sample : samples) sample.posture = standing_posture(Eigen::Vector3d(-0.3, 0.5, 1.0));
  const std::string good = trajectory_csv(model, samples);
  const std::string header = good.substr(0, good.find('\n') + 1);
  const auto row = [&](int line) {
    std::istringstream in(good);
    std::string text;
    for (int i = 0; i <= line; ++i) std::getline(in, text);
    return csv_cells(text);
  };
  const auto with_cell = [&](int line, std::size_t cell, const std::string& value, int number = -1) {
    std::vector<std::string> cells = row(line);
    cells[cell] = value;
    if (number >= 0) cells[0] = std::to_string(number);
    std::string text;
    for (std::size_t c = 0; c < cells.size(); ++c) text += (c ? "," : "") + cells[c];
    return text + "\n";
  };
  const std::string first = with_cell(1, 0, "0"), second = with_cell(2, 0, "1");
  const struct {
    std::string name, text, problem;
  } cases[] = {
      {"quaternion.csv", header + with_cell(1, 3, "0.5"), "line 2: the root's rotation is not a unit quaternion"},
      {"move.csv", header + with_cell(1, 2, "-2"), "line 2: move -2 is not a move"},
      {"backwards.csv", header + first + with_cell(2, 1, "-1"), "line 3: a sample before the one above it"},
      {"numbering.csv", header + first + with_cell(2, 0, "5"), "line 3: samples must be numbered from 0 in order"},
      {"finite.csv", header + with_cell(1, 8, "nan"), "line 2: 'nan' is not finite"},
      {"far.csv", header + with_cell(1, 19, "1e9"), "line 2: root_x = 1000000000 is outside [-1000, 1000] m"},
      {"joint.csv", header + with_cell(1, 19 + kRootDof, "40"), "is outside a turn of the joint's limits"},
  };
  for (const auto& c : cases) {
    const fs::path file = trajectory_file(c.name, c.text);
    try {
      read_trajectory_csv(model, file);
      ADD_FAILURE() << c.name << " was read";
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), file.string()) << c.name;
      EXPECT_NE(e.problem().find(c.problem), std::string::npos) << c.name << ": " << e.problem();
    }
  }
  EXPECT_NO_THROW(read_trajectory_csv(model, trajectory_file("good.csv", header + first + second)));
}

}  // namespace
}  // namespace crux
