#pragma once
// crux view's output besides its SVG: where the body is at the drawn posture (root,
// centre of mass, grasp points), as JSON, or a one-line text.

#include <string>

#include <nlohmann/json.hpp>

#include "body/body_model.hpp"
#include "body/wall_penetration.hpp"
#include "climbing/stance_check.hpp"
#include "outputs/perform_folder.hpp"
#include "outputs/run_folder.hpp"

namespace crux {

struct ViewCaption {
  std::string svg;  // the file written
  std::string title;
  std::string subtitle;
};

// Step `step` of a run's climb, or a wall's start posture.
ViewCaption run_view_caption(const RunFolder& folder, const RecordedClimb& climb, int step, const std::string& svg);
ViewCaption wall_view_caption(const Wall& wall, const std::string& svg);
// Step `step` of a climb performed in MuJoCo: the start at rest, or the end of a move.
ViewCaption performed_view_caption(const PerformFolder& folder, int step, const std::string& svg);

// The caption with, when the body at `posture` passes through the wall (body/wall_penetration),
// a note of how far and which part: the kinematic model ignores the wall, as the paper's
// does, so a drawn posture may pass through it.
ViewCaption with_wall_note(ViewCaption caption, const BodyModel& model, const Posture& posture);

// The caption with the static model's verdict on the posture: "static model: held at
// effort 0.11", "... not held: effort 1.40 (left shoulder flexion)" or "... cannot balance".
ViewCaption with_stance_note(ViewCaption caption, const BodyModel& model, const StanceLoads& loads);

// "the head is 0.061 m inside the wall", or "" when the body stays out of it.
std::string wall_penetration_note(const BodyModel& model, const WallPenetration& penetration);

// With the static model's `loads` (null under the kinematic model): their `stance`.
nlohmann::ordered_json view_json(const BodyModel& model, const Posture& posture, const ViewCaption& caption,
                                 const StanceLoads* loads = nullptr);
std::string view_text(const ViewCaption& caption);

// A posture simulated in MuJoCo, `sample` of a performed climb: view_json's keys (the
// body turned by the root's rotation) with the rotation, the time and the hold forces.
nlohmann::ordered_json performed_view_json(const BodyModel& model, const TrajectorySample& sample,
                                           const ViewCaption& caption);

}  // namespace crux
