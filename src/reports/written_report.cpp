#include "reports/written_report.hpp"

#include <cmath>

#include <fmt/format.h>

#include "common/counted.hpp"

namespace crux {

namespace {

int replay_frames(const ReportPage& page) {
  return page.replay.is_null() ? 0 : page.replay["frames"]["count"].get<int>();
}

std::size_t replay_moves(const ReportPage& page) { return page.replay.is_null() ? 0 : page.replay["moves"].size(); }

std::size_t climb_moves(const ReportPage& page) {
  return page.replay.is_null() ? 0 : page.replay.value("climb_moves", replay_moves(page));
}

nlohmann::ordered_json performed_json(const ReportPage& page) {
  if (!page.performed) return nullptr;
  const PerformedSection& p = *page.performed;
  return {{"folder", p.folder},
          {"outcome", p.outcome},
          {"moves", p.moves.size()},
          {"frames", p.replay.is_null() ? 0 : p.replay["frames"]["count"].get<int>()}};
}

std::string performed_text(const ReportPage& page) {
  if (!page.performed) return "";
  const PerformedSection& p = *page.performed;
  return fmt::format("performed in MuJoCo ({}): {}\n", p.folder, p.outcome);
}

}  // namespace

nlohmann::ordered_json written_report_json(const ReportPage& page, const std::string& run_name, const std::string& file,
                                           std::size_t bytes, double seconds) {
  nlohmann::ordered_json out;
  out["report"] = file;
  out["bytes"] = bytes;
  out["figures"] = page.figures.size();
  out["replay_run"] = run_name;
  out["replay_climb"] = page.replay.is_null() ? nlohmann::ordered_json() : nlohmann::ordered_json(page.replay_climb);
  // Episodes are numbered from 1 wherever crux shows one, as in the paper's Fig. 4.
  out["replay_episode"] = page.replay_episode < 0 ? -1 : page.replay_episode + 1;
  out["replay_attempt"] = page.replay_attempt;
  out["replay_reason"] = page.replay_reason;
  out["replay_moves"] = replay_moves(page);
  out["climb_moves"] = climb_moves(page);
  out["replay_frames"] = replay_frames(page);
  out["climb_postures"] = page.climb_postures;
  out["postures_in_wall"] = page.postures_in_wall;
  out["deepest_in_wall_m"] =
      page.deepest_in_wall_posture < 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(page.deepest_in_wall_m);
  if (!page.stance_effort_four.empty()) {
    // +infinity (no balance) is null in JSON.
    const auto series = [](const std::vector<double>& values) {
      nlohmann::ordered_json out = nlohmann::ordered_json::array();
      for (const double v : values)
        out.push_back(std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json());
      return out;
    };
    out["stance_effort"] = {{"on_four_holds", series(page.stance_effort_four)},
                            {"on_three_holds", series(page.stance_effort_three)}};
  }
  out["performed"] = performed_json(page);
  out["seconds"] = seconds;
  return out;
}

std::string written_report_text(const ReportPage& page, const std::string& run_name, const std::string& file,
                                std::size_t bytes, double seconds) {
  const std::string written = fmt::format("wrote {} ({:.1f} MB, {}", file, static_cast<double>(bytes) / 1e6,
                                          counted(page.figures.size(), "figure"));
  if (page.replay.is_null() && page.replay_reason.empty() && page.performed) {
    return fmt::format("{}) in {:.2f} s\n{}", written, seconds, performed_text(page));
  }
  if (page.replay.is_null()) {
    return fmt::format("{}, no replay) in {:.2f} s\nno replay: {}\n{}", written, seconds, page.replay_reason,
                       performed_text(page));
  }
  const std::string moves = replay_moves(page) < climb_moves(page)
                                ? fmt::format("the first {} of {} moves", replay_moves(page), climb_moves(page))
                                : counted(replay_moves(page), "move");
  return fmt::format("{}, a replay of {} with {}) in {:.2f} s\nreplayed: {}\n{}", written, run_name, moves, seconds,
                     page.replay_reason, performed_text(page));
}

}  // namespace crux
