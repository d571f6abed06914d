#pragma once
// `crux report`: one self-contained HTML page for an output folder (docs/OUTPUTS.md,
// "crux report"). Everything it shows comes from the folder's files; every script and
// style is inlined and a Content-Security-Policy forbids the page any request.

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace crux {

struct ReportFigure {
  std::string title;
  std::string caption;
  std::string svg;  // a standalone SVG document; its XML declaration is dropped when inlined
};

// A climb performed in MuJoCo (a crux perform folder), shown on a page of its own or beside
// a run's replay (README's main job: the paper's kinematic replay and a performed plan).
struct PerformedMoveRow {
  std::string limb;
  int hold_id = 0;
  bool performed = false;
  std::string cause;  // why it failed ("" when performed), in words
  double max_torque_ratio = 0.0;
};
struct PerformedSection {
  std::string title;    // what was performed, on which wall
  std::string outcome;  // how far it went and why it stopped, in words
  std::string folder;   // the crux perform folder it was read from
  std::vector<PerformedMoveRow> moves;
  nlohmann::ordered_json replay;  // performed_replay_data(); null when nothing was performed
};

struct ReportPage {
  std::string title;
  nlohmann::json summary;  // the folder's summary.json
  std::vector<ReportFigure> figures;
  std::string replay_title;
  std::string replay_climb;       // its kind: greedy, last or episode (RecordedClimb)
  int replay_episode = -1;        // its episode's index from 0; -1 for the greedy climb
  int replay_attempt = 1;         // which attempt of its episode, from 1 (a fall starts another)
  std::string replay_reason;      // which climb it is and why, or why there is no replay (shown_climb_reason)
  nlohmann::ordered_json replay;  // replay_data(); null for none
  // The replayed climb's recorded postures that pass through the wall (body/wall_penetration),
  // and what the deepest of them says (view_description's wall_penetration_note) at which posture.
  std::size_t postures_in_wall = 0;
  std::size_t climb_postures = 0;
  double deepest_in_wall_m = 0.0;
  std::string deepest_in_wall;
  int deepest_in_wall_posture = -1;
  // Under the static model, each stance's effort on four and on three holds (the effort
  // figure's); empty otherwise.
  std::vector<double> stance_effort_four, stance_effort_three;
  std::optional<PerformedSection> performed;
  std::string_view style;   // the page's CSS
  std::string_view script;  // the replay's script (three.js bundled in)
};

std::string html_report(const ReportPage& page);

}  // namespace crux
