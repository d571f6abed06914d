#pragma once
// crux model's output: what the body is (degrees of freedom, size, mass, joint limits
// and the segment lengths its kinematics actually uses), as JSON or text.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "body/body_model.hpp"

namespace crux {

struct SegmentLength {
  std::string name;  // "parent joint -> child joint" or "carrier joint -> grasp frame"
  double length_m;
};

// Distance between consecutive distinct joint origins along the body, and from each
// grasp point's carrier joint to the grasp point, at the standing posture.
std::vector<SegmentLength> segment_lengths(const BodyModel& model);

nlohmann::ordered_json model_json(const BodyModel& model);
std::string model_text(const BodyModel& model);

}  // namespace crux
