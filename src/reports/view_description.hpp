#pragma once
// crux view's output besides its SVG: where the body is at the drawn posture (root,
// centre of mass, grasp points), as JSON, or a one-line text.

#include <string>

#include <nlohmann/json.hpp>

#include "body/body_model.hpp"

namespace crux {

struct ViewCaption {
  std::string svg;  // the file written
  std::string title;
  std::string subtitle;
};

nlohmann::ordered_json view_json(const BodyModel& model, const Posture& posture, const ViewCaption& caption);
std::string view_text(const ViewCaption& caption);

}  // namespace crux
