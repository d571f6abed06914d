#include "outputs/perform_folder.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "common/input_error.hpp"
#include "outputs/output_folder.hpp"
#include "outputs/trajectory_csv.hpp"
#include "support/test_models.hpp"
#include "support/test_walls.hpp"

namespace crux {
namespace {

namespace fs = std::filesystem;

// perform.json as crux perform writes it, with the keys the reader takes: a plan of three
// moves whose second failed.
nlohmann::ordered_json perform_record() {
  return nlohmann::ordered_json::parse(R"({
    "wall": "w", "physics_model": "static", "found": true, "length": 3,
    "reached_top": false, "max_torque_ratio": 0.9, "simulated_s": 4.5,
    "start": {"performed": true, "cause": null},
    "moves": [
      {"limb": "right_hand", "hold": 5, "performed": true, "cause": null, "max_torque_ratio": 0.5},
      {"limb": "left_hand", "hold": 2, "performed": false, "cause": "hand_slipped", "max_torque_ratio": 0.9}],
    "climb": "the wall's exact plan"})");
}

struct PerformFolderFixture : ::testing::Test {
  const BodyModel& model = testing::human_model();
  // Hold ids 1 to 5, as wall_with_holds numbers them.
  Wall wall = testing::wall_with_holds({{-0.25, 1.75}, {0.25, 1.75}, {-0.15, 0.45}, {0.15, 0.45}, {-0.25, 1.95}});

  fs::path write(const std::string& name, const nlohmann::ordered_json& record) const {
    const fs::path folder = testing::temporary_path(name);
    std::vector<TrajectorySample> samples(3);
    for (int i = 0; i < 3; ++i) {
      samples[i].time = 0.02 * i;
      samples[i].move = i - 1;
      samples[i].posture = standing_posture({-0.3, 0.0, 1.0});
    }
    write_perform_folder(folder, "", wall, record, trajectory_csv(model, samples), "");
    return folder;
  }
};

TEST_F(PerformFolderFixture, ReadsTheClimbItsMovesAndItsTrajectory) {
  const fs::path folder = write("perform-read", perform_record());
  ASSERT_TRUE(is_perform_folder(folder));
  const PerformFolder read = read_perform_folder(folder, model);
  EXPECT_EQ(read.climb, "the wall's exact plan");
  EXPECT_EQ(read.physics, "static");
  EXPECT_TRUE(read.found);
  EXPECT_EQ(read.planned_moves, 3);
  EXPECT_TRUE(read.start_held);
  ASSERT_EQ(read.moves.size(), 2u);
  EXPECT_EQ(read.moves[0].limb, Limb::RightHand);
  EXPECT_EQ(read.moves[0].hold, wall.index_of(5));
  EXPECT_TRUE(read.moves[0].performed);
  EXPECT_EQ(read.moves[1].cause, MoveFailure::HandSlipped);
  EXPECT_FALSE(read.reached_top);
  EXPECT_EQ(read.simulated_s, 4.5);
  EXPECT_EQ(read.trajectory.size(), 3u);
  EXPECT_EQ(read.trajectory[2].move, 1);
  EXPECT_FALSE(is_perform_folder(folder / "nothing"));
}

// A search that found no plan performed nothing, and its folder reads back so.
TEST_F(PerformFolderFixture, AFolderWithoutAPlanReadsAsNothingPerformed) {
  const nlohmann::ordered_json record = nlohmann::ordered_json::parse(R"({
    "wall": "w", "physics_model": "dynamic", "found": false, "length": -1,
    "reached_top": false, "max_torque_ratio": 0.0, "simulated_s": 0.0, "start": null, "moves": [],
    "climb": "the wall's exact plan"})");
  const PerformFolder read = read_perform_folder(write("perform-none", record), model);
  EXPECT_FALSE(read.found);
  EXPECT_EQ(read.planned_moves, 0);
  EXPECT_FALSE(read.start_held);
  EXPECT_TRUE(read.moves.empty());
}

TEST_F(PerformFolderFixture, ABadRecordIsOneErrorNamingPerformJson) {
  const auto problem = [&](const std::string& name, const nlohmann::ordered_json& record) {
    const fs::path folder = write(name, record);
    try {
      read_perform_folder(folder, model);
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), (folder / "perform.json").string()) << name;
      return e.problem();
    }
    return std::string("read");
  };
  nlohmann::ordered_json record = perform_record();
  record["moves"][0]["hold"] = 42;
  EXPECT_EQ(problem("perform-hold", record), "moves[0].hold names hold 42, which wall.json does not have");
  record = perform_record();
  record["moves"][0]["cause"] = "hit_wall";
  EXPECT_EQ(problem("perform-cause", record), "moves[0].cause must be null exactly when performed");
  record = perform_record();
  record["moves"][1]["limb"] = "tail";
  EXPECT_NE(problem("perform-limb", record).find("moves[1].limb"), std::string::npos);
  record = perform_record();
  std::swap(record["moves"][0], record["moves"][1]);
  EXPECT_EQ(problem("perform-order", record), "moves[0] failed, so it must be the climb's last move");
  record = perform_record();
  record["length"] = 1;
  EXPECT_EQ(problem("perform-length", record), "moves has 2 moves, more than the climb's length 1");
  record = perform_record();
  record.erase("climb");
  EXPECT_EQ(problem("perform-missing", record), "climb is missing");
  record = perform_record();
  record["moves"].erase(1);
  EXPECT_EQ(problem("perform-stopped", record),
            "reached_top, start and moves disagree: the moves go on from a start that held until one fails");
  record = perform_record();
  record["found"] = false;
  EXPECT_EQ(problem("perform-found", record), "length must be -1 exactly when found is false");
  const fs::path folder = write("perform-text", perform_record());
  std::ofstream(folder / "perform.json") << "{ not json";
  EXPECT_THROW(read_perform_folder(folder, model), InputError);
}

}  // namespace
}  // namespace crux
