#include "reports/stance_survey_description.hpp"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "experiments/statistics.hpp"
#include "physics/contact_model.hpp"

namespace crux {

namespace {

// Per wall (the unit: stances on one wall are not independent), the share held on four
// holds, on three among those, and on both; walls without a stance do not count.
struct WallShares {
  MeanInterval four, three_of_four, both;
  int walls = 0;
};

WallShares wall_shares(const StanceSurvey& survey) {
  std::vector<double> four, three_of_four, both;
  for (const WallStances& wall : survey.walls) {
    const StanceTally& t = wall.tally;
    if (t.stances == 0) continue;
    four.push_back(static_cast<double>(t.four_held) / t.stances);
    both.push_back(static_cast<double>(t.three_held) / t.stances);
    if (t.four_held > 0) three_of_four.push_back(static_cast<double>(t.three_held) / t.four_held);
  }
  return {mean_interval(four), mean_interval(three_of_four), mean_interval(both), static_cast<int>(four.size())};
}

nlohmann::ordered_json share_json(const MeanInterval& share) {
  return {{"mean", share.mean}, {"ci95_half_width", share.half_width}, {"walls", share.n}};
}

// Failures, most frequent first (ties by name).
std::vector<std::pair<std::string, int>> ranked(const std::map<std::string, int>& failures) {
  std::vector<std::pair<std::string, int>> sorted(failures.begin(), failures.end());
  // std::sort with the name as the tie-break, not std::stable_sort, whose temporary buffer
  // libstdc++ 12 frees in a way ASan reports as a mismatch (as in views/body_svg).
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) {
    return a.second != b.second ? a.second > b.second : a.first < b.first;
  });
  return sorted;
}

nlohmann::ordered_json failures_json(const std::map<std::string, int>& failures) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [name, count] : ranked(failures)) out[name] = count;
  return out;
}

std::string failures_text(const std::map<std::string, int>& failures, int of) {
  if (failures.empty()) return "none\n";
  std::string text;
  for (const auto& [name, count] : ranked(failures)) {
    text += fmt::format("    {:<28} {:>6}  ({:.1f} %)\n", name, count, 100.0 * count / of);
  }
  return text;
}

}  // namespace

nlohmann::ordered_json stance_survey_json(const StanceSurvey& survey, const StanceSurveyParameters& parameters) {
  const WallShares shares = wall_shares(survey);
  const PhysicsParameters& physics = parameters.climbing.physics;
  nlohmann::ordered_json walls = nlohmann::ordered_json::array();
  for (const WallStances& wall : survey.walls) {
    walls.push_back({{"seed", wall.seed},
                     {"start_reached", wall.start_reached},
                     {"stances", wall.tally.stances},
                     {"four_held", wall.tally.four_held},
                     {"three_held", wall.tally.three_held}});
  }
  return {{"format", "crux-stances"},
          {"version", 1},
          {"wall_seed", parameters.wall_seed},
          {"wall_count", parameters.wall_count},
          {"moves_per_wall", parameters.moves},
          {"incline_deg", parameters.walls.incline_deg},
          {"physics",
           {{"friction", physics.friction},
            {"grip_n", physics.grip},
            {"support_angle_deg", physics.support_angle_deg},
            {"friction_cone_faces", kFrictionConeFaces}}},
          {"stances", survey.total.stances},
          {"four_held", survey.total.four_held},
          {"three_held", survey.total.three_held},
          {"share_four_held", share_json(shares.four)},
          {"share_three_held_of_four_held", share_json(shares.three_of_four)},
          {"share_held", share_json(shares.both)},
          {"path_samples_per_move", parameters.path_samples},
          {"path_moves", survey.total.path_moves},
          {"path_moves_failing", survey.total.path_moves_failing},
          {"path_samples", survey.total.path_samples},
          {"path_samples_failing", survey.total.path_samples_failing},
          {"four_failures", failures_json(survey.total.four_failures)},
          {"three_failures", failures_json(survey.total.three_failures)},
          {"walls", walls}};
}

std::string stance_survey_text(const StanceSurvey& survey, const StanceSurveyParameters& parameters) {
  const WallShares shares = wall_shares(survey);
  const StanceTally& total = survey.total;
  const int unreached = static_cast<int>(
      std::count_if(survey.walls.begin(), survey.walls.end(), [](const WallStances& w) { return !w.start_reached; }));
  std::string text = fmt::format(
      "{} distinct stances reached by {} random kinematic moves (body out of the wall) on each of {} random walls "
      "(wall seed {}, incline {} degrees; {} with an unreachable start left out)\n",
      total.stances, parameters.moves, parameters.wall_count, parameters.wall_seed, parameters.walls.incline_deg,
      unreached);
  const auto share = [](const MeanInterval& s) {
    return fmt::format("{:.1f} % +- {:.1f} (mean over {} walls, 95 % interval)", 100.0 * s.mean, 100.0 * s.half_width,
                       s.n);
  };
  text += fmt::format("  held on four holds:              {}\n", share(shares.four));
  text += fmt::format("  ... and on the three left:       {}\n", share(shares.three_of_four));
  text += fmt::format("  held as the static model asks:   {}\n", share(shares.both));
  text += fmt::format("  why {} stances fail on four holds: {}", total.stances - total.four_held,
                      total.four_failures.empty() ? "" : "\n");
  text += failures_text(total.four_failures, total.stances - total.four_held);
  text += fmt::format("  why {} stances held on four fail on three: {}", total.four_held - total.three_held,
                      total.three_failures.empty() ? "" : "\n");
  text += failures_text(total.three_failures, total.four_held - total.three_held);
  const auto percent = [](int part, int whole) { return whole > 0 ? 100.0 * part / whole : 0.0; };
  text += fmt::format(
      "  the movements between stances, as the replay draws them ({} samples a move): of {} reached moves that start "
      "held on the three holds they keep, {} ({:.1f} %) pass through a posture that does not hold on them ({} of {} "
      "samples, {:.1f} %)\n",
      parameters.path_samples, total.path_moves, total.path_moves_failing,
      percent(total.path_moves_failing, total.path_moves), total.path_samples_failing, total.path_samples,
      percent(total.path_samples_failing, total.path_samples));
  text +=
      "  (grip: it balances once the hands' grip is unbounded; contacts: no forces in the friction cones balance "
      "it; a joint's name: it balances, above that joint's torque limit)\n";
  return text;
}

}  // namespace crux
