#pragma once
// A sequence of postures as CSV: one row per posture, one column per joint of the body
// (the URDF's names), each value the shortest text that reads back to the same double.
// climb.csv and greedy_climb.csv of a run and the IK path of `crux ik -o` share it.

#include <span>
#include <string>
#include <vector>

#include "body/body_model.hpp"

namespace crux {

// A column written between the index and the joints: its name and one cell per posture.
struct PostureCsvColumn {
  std::string name;
  std::vector<std::string> cells;
};

// The first column is named `index_name` and counts postures from 0.
std::string posture_csv(const BodyModel& model, std::span<const Posture> postures, const char* index_name,
                        const std::vector<PostureCsvColumn>& columns = {});

}  // namespace crux
