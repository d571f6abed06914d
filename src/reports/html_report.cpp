#include "reports/html_report.hpp"

#include <iterator>

#include <fmt/format.h>

#include "common/counted.hpp"
#include "experiments/paper_experiment.hpp"
#include "experiments/stratified_bootstrap.hpp"
#include "experiments/table_one.hpp"
#include "learning/action_selection.hpp"
#include "reports/paper_reference.hpp"
#include "reports/replay_data.hpp"
#include "views/svg_document.hpp"

namespace crux {
namespace {

using Json = nlohmann::json;

// A JSON value from the summary, or null when the path does not exist.
const Json& at(const Json& json, std::initializer_list<std::string_view> path) {
  static const Json null;
  const Json* node = &json;
  for (const std::string_view key : path) {
    if (!node->is_object()) return null;
    const auto found = node->find(key);
    if (found == node->end()) return null;
    node = &*found;
  }
  return *node;
}

std::string number(const Json& value, const char* format = "{:.3g}") {
  if (!value.is_number()) return "&ndash;";
  return fmt::format(fmt::runtime(format), value.get<double>());
}

// A count from the summary with its noun ("1 seed", "6 seeds"); a dash for the count
// when the summary lacks it.
std::string counted_value(const Json& value, std::string_view singular) {
  return value.is_number_integer() ? counted(value.get<long long>(), singular) : "&ndash; " + counted_noun(2, singular);
}

std::string interval(const Json& value, const char* format = "{:.3g}") {
  if (!value.is_array() || value.size() != 2) return "&ndash;";
  return fmt::format("[{}, {}]", number(value[0], format), number(value[1], format));
}

class Page {
 public:
  explicit Page(const ReportPage& page) : page_(page) {}

  std::string render() {
    out_ += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    out_ += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    // Nothing may leave the page: no fetch, image, font or frame from anywhere.
    out_ +=
        "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src 'unsafe-inline'; "
        "style-src 'unsafe-inline'; img-src data: blob:\">\n";
    out_ += "<link rel=\"icon\" href=\"data:,\">\n";  // or the browser asks the server for /favicon.ico
    append_format(out_, "<title>{}</title>\n<style>\n{}\n</style>\n</head>\n<body>\n<main>\n", xml_escaped(page_.title),
                  page_.style);
    // A crux perform folder's page has no run: only the performed climb.
    const bool performed_only = page_.summary.is_null() && page_.performed;
    if (!performed_only) {
      write_header();
      const bool experiment = at(page_.summary, {"kind"}) == "experiment";
      if (experiment) {
        write_table_one();
        write_statistics();
      } else {
        write_run_facts();
      }
      write_figures();
      write_replay();
    } else {
      append_format(out_, "<h1>{}</h1>\n", xml_escaped(page_.title));
    }
    write_performed();
    out_ += "</main>\n";
    const bool performed_replay = page_.performed && !page_.performed->replay.is_null();
    if (!page_.replay.is_null()) write_data("crux-replay-data", page_.replay);
    if (performed_replay) write_data("crux-performed-data", page_.performed->replay);
    if (!page_.replay.is_null() || performed_replay) append_format(out_, "<script>\n{}\n</script>\n", page_.script);
    out_ += "</body>\n</html>\n";
    return std::move(out_);
  }

 private:
  void write_data(std::string_view id, const nlohmann::ordered_json& replay) {
    std::string data = replay.dump();
    // Inside <script>, "</script" would end the element and "<!--" change how it is read;
    // JSON reads the escape \u003c as "<".
    for (std::size_t at = data.find('<'); at != std::string::npos; at = data.find('<', at + 6)) {
      data.replace(at, 1, "\\u003c");
    }
    append_format(out_, "<script type=\"application/json\" id=\"{}\">{}</script>\n", id, data);
  }

  void write_header() {
    const Json& s = page_.summary;
    append_format(out_, "<h1>{}</h1>\n<dl class=\"facts\">\n", xml_escaped(page_.title));
    const auto fact = [&](std::string_view name, const std::string& value) {
      append_format(out_, "<dt>{}</dt><dd>{}</dd>\n", name, value);
    };
    const auto text = [](const Json& value) {
      return value.is_string() ? xml_escaped(value.get<std::string>())
             : value.is_null() ? std::string("&ndash;")
                               : xml_escaped(value.dump());
    };
    fact("crux", text(at(s, {"provenance", "crux_version"})) + " (" + text(at(s, {"provenance", "git_commit"})) + ")");
    fact("body model", text(at(s, {"provenance", "urdf"})));
    fact("seed", text(at(s, {"seed"})));
    fact("design", fmt::format("{} &times; {} per wall, {} per run, {} IK solver",
                               counted_value(at(s, {"wall_pairs"}), "wall pair"),
                               counted_value(at(s, {"seeds_per_wall"}), "seed"),
                               counted_value(at(s, {"iterations"}), "iteration"), text(at(s, {"solver"}))));
    out_ += "</dl>\n";
  }

  // Table I (paper, section IV): ours with the paper's values beside them.
  void write_table_one() {
    const PaperTableOne& paper = paper_table_one();
    out_ += "<section id=\"table-one\">\n<h2>Table I: actions by regime</h2>\n";
    append_format(out_,
                  "<p>Pooled over the runs of each condition; the paper's values in brackets (section IV, Table I). "
                  "Beginning = the first {}. The control condition, absent from the paper, learns on the transfer "
                  "walls without transferred knowledge.</p>\n",
                  counted_value(at(page_.summary, {"beginning_iterations"}), "iteration"));
    static const char* const metrics[3] = {"vertical rise of e0 (cm)", "success rate (%)", "actions per run"};
    for (int w = 0; w < 2; ++w) {
      append_format(out_, "<table class=\"numbers\">\n<caption>{}</caption>\n<thead><tr><th></th><th></th>",
                    enum_name(static_cast<Window>(w)));
      for (const Condition condition : kConditions) append_format(out_, "<th>{}</th>", enum_name(condition));
      out_ += "</tr></thead>\n<tbody>\n";
      for (int metric = 0; metric < 3; ++metric) {
        for (int r = 0; r < kRegimeCount; ++r) {
          out_ += "<tr>";
          if (r == 0) append_format(out_, "<th rowspan=\"3\">{}</th>", metrics[metric]);
          append_format(out_, "<th>{}</th>", enum_name(static_cast<Regime>(r)));
          for (int c = 0; c < 3; ++c) {
            const Json& stats =
                at(page_.summary, {"table1", enum_name(kConditions[c]), enum_name(static_cast<Window>(w)),
                                   enum_name(static_cast<Regime>(r))});
            std::string value;
            if (metric == 0) value = number(at(stats, {"vertical_cm"}), "{:.1f}");
            if (metric == 1) {
              const Json& rate = at(stats, {"success_rate"});
              value = rate.is_number() ? fmt::format("{:.1f}", 100 * rate.get<double>()) : "&ndash;";
            }
            if (metric == 2) value = number(at(stats, {"actions"}), "{:.0f}");
            if (metric < 2 && c < 2) {
              const double reference = metric == 0 ? paper.vertical_cm[c][w][r] : 100 * paper.success_rate[c][w][r];
              value += fmt::format(" <span class=\"paper\">({:.1f})</span>", reference);
            }
            append_format(out_, "<td>{}</td>", value);
          }
          out_ += "</tr>\n";
        }
      }
      out_ += "</tbody>\n</table>\n";
    }
    out_ += "</section>\n";
  }

  void write_statistics() {
    const Json& comparisons = at(page_.summary, {"transfer_vs_control"});
    if (!comparisons.is_object()) return;
    out_ += "<section id=\"statistics\">\n<h2>Transfer minus control</h2>\n";
    append_format(
        out_,
        "<p>Each transfer run is paired with a control run on the same wall and seed. Differences are averaged per "
        "wall, then over the {}: 95&nbsp;% intervals by Student's t over walls and by a cluster bootstrap over "
        "walls; p from a two-sided t-test over walls, not corrected for the number of metrics.</p>\n",
        counted_value(at(page_.summary, {"wall_pairs"}), "wall"));
    out_ +=
        "<table class=\"numbers\">\n<thead><tr><th>metric</th><th>better</th><th>transfer</th><th>control</th>"
        "<th>difference</th><th>95&nbsp;% CI (t)</th><th>95&nbsp;% CI (bootstrap)</th><th>p</th><th>walls</th>"
        "</tr></thead>\n<tbody>\n";
    for (const auto& [metric, values] : comparisons.items()) {
      const Json& difference = at(values, {"transfer_minus_control"});
      append_format(
          out_,
          "<tr><th title=\"{}\">{}</th><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
          "<td>{}</td></tr>\n",
          xml_escaped(at(values, {"description"}).is_string() ? at(values, {"description"}).get<std::string>() : ""),
          xml_escaped(metric), at(values, {"higher_is_better"}) == true ? "higher" : "lower",
          number(at(values, {"transfer", "mean"})), number(at(values, {"control", "mean"})),
          number(at(difference, {"mean"})), interval(at(difference, {"ci95_t_over_walls"})),
          interval(at(difference, {"ci95_cluster_bootstrap"})), number(at(difference, {"p_value"}), "{:.3f}"),
          number(at(difference, {"walls"}), "{:.0f}"));
    }
    out_ += "</tbody>\n</table>\n";
    write_stratified_statistics(comparisons);
    out_ += "</section>\n";
  }

  // rliable's view beside the t-intervals, when the summary has it.
  void write_stratified_statistics(const Json& comparisons) {
    if (comparisons.empty() || !at(comparisons.begin().value(), {"iqm"}).is_object()) return;
    out_ +=
        "<p>rliable's view (Agarwal et al., NeurIPS 2021): interquartile means (IQM) over runs and the probability "
        "that transfer beats control on a wall, with 95&nbsp;% stratified bootstrap intervals: the walls are kept "
        "and their seeds resampled, so these intervals leave out wall-to-wall variation, which the t-intervals "
        "include.</p>\n<table class=\"numbers\">\n<thead><tr><th>metric</th><th>IQM transfer</th><th>IQM "
        "control</th><th>IQM difference</th><th>P(transfer better)</th></tr></thead>\n<tbody>\n";
    // An interval only where the bootstrap had seeds to resample (summary.json's null).
    const auto estimate = [](const Json& e, const char* format) {
      if (at(e, {"low"}).is_null()) return number(at(e, {"value"}), format);
      return fmt::format("{} [{}, {}]", number(at(e, {"value"}), format), number(at(e, {"low"}), format),
                         number(at(e, {"high"}), format));
    };
    for (const auto& [metric, values] : comparisons.items()) {
      append_format(out_, "<tr><th>{}</th><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n", xml_escaped(metric),
                    estimate(at(values, {"iqm", "transfer"}), "{:.3g}"),
                    estimate(at(values, {"iqm", "control"}), "{:.3g}"),
                    estimate(at(values, {"iqm", "difference"}), "{:+.3g}"),
                    estimate(at(values, {"probability_of_improvement"}), "{:.2f}"));
    }
    out_ += "</tbody>\n</table>\n";
    if (at(at(comparisons.begin().value(), {"iqm", "difference"}), {"low"}).is_null()) {
      append_format(out_, "<p>No intervals: {}.</p>\n", kNoStratifiedIntervals);
    }
  }

  void write_run_facts() {
    out_ += "<section id=\"run\">\n<h2>The run</h2>\n<table class=\"numbers\">\n<tbody>\n";
    for (const Condition c : kConditions) {
      const char* condition = enum_name(c);
      const Json& facts = at(page_.summary, {"run_facts", condition});
      if (!facts.is_array() || facts.empty()) continue;
      const Json& run = facts[0];
      append_format(out_, "<tr><th>condition</th><td>{}</td></tr>\n", condition);
      for (const char* key : {"episodes", "greedy_length", "take_off_iteration", "ik_solves", "explored_pairs"}) {
        append_format(out_, "<tr><th>{}</th><td>{}</td></tr>\n", key, number(at(run, {key}), "{:.0f}"));
      }
    }
    out_ += "</tbody>\n</table>\n</section>\n";
  }

  void write_figures() {
    if (page_.figures.empty()) return;
    out_ += "<section id=\"figures\">\n<h2>Figures</h2>\n";
    for (const ReportFigure& figure : page_.figures) {
      std::string_view svg = figure.svg;
      if (svg.starts_with("<?xml")) svg.remove_prefix(svg.find("?>") + 2);
      append_format(out_, "<figure>\n<h3>{}</h3>\n{}\n<figcaption>{}</figcaption>\n</figure>\n",
                    xml_escaped(figure.title), svg, xml_escaped(figure.caption));
    }
    out_ += "</section>\n";
  }

  // The replay names the climb it shows and why that one (the greedy policy's may not
  // reach the top); without a climb to show, the section says why there is none.
  void write_replay() {
    if (page_.replay.is_null()) {
      if (!page_.replay_reason.empty()) {
        append_format(out_, "<section id=\"replay\">\n<h2>Replay</h2>\n<p>No replay: {}.</p>\n</section>\n",
                      xml_escaped(page_.replay_reason));
      }
      return;
    }
    append_format(out_, "<section id=\"replay\">\n<h2>Replay: {}</h2>\n", xml_escaped(page_.replay_title));
    if (!page_.replay_reason.empty()) append_format(out_, "<p>Replayed: {}.</p>\n", xml_escaped(page_.replay_reason));
    if (page_.postures_in_wall > 0) {
      append_format(out_,
                    "<p class=\"in-wall\">{} of the climb's {} recorded postures pass through the wall (crux's "
                    "default kinematic model ignores the wall, as the paper's does); the deepest: {}, at posture "
                    "{}.</p>\n",
                    page_.postures_in_wall, page_.climb_postures, xml_escaped(page_.deepest_in_wall),
                    page_.deepest_in_wall_posture);
    }
    // A page built by hand (the tests') may carry a replay without moves.
    const std::size_t shown = page_.replay.contains("moves") ? page_.replay["moves"].size() : 0;
    const std::size_t moves = page_.replay.value("climb_moves", shown);
    if (shown < moves) {
      append_format(out_,
                    "<p class=\"cut\">This climb has {} moves; the replay shows its first {} (crux report "
                    "--replay-moves, at most {}).</p>\n",
                    moves, shown, kMaxReplayMoves);
    }
    out_ +=
        "<p>The climb move by move. Between two recorded postures the body follows the path of the paper's "
        "gradient-descent IK (Algorithm 1). Drag to orbit, scroll to zoom; space plays and pauses, the arrow keys "
        "step.</p>\n";
    if (page_.performed) {
      out_ +=
          "<p>This replay draws the learnt climb as the paper's model has it: postures from the IK, nothing "
          "simulated. The section after it shows a climb performed in MuJoCo.</p>\n";
    }
    out_ += "<div id=\"crux-replay\"></div>\n</section>\n";
  }

  // A climb performed in MuJoCo: what was performed, how far it went, each move's outcome,
  // and the simulated motion (not the IK's drawing).
  void write_performed() {
    if (!page_.performed) return;
    const PerformedSection& p = *page_.performed;
    append_format(out_, "<section id=\"performed\">\n<h2>Performed in MuJoCo: {}</h2>\n<p>{}</p>\n",
                  xml_escaped(p.title), xml_escaped(p.outcome));
    append_format(out_,
                  "<p>Read from <code>{}</code>. Not the IK's drawing: the motion MuJoCo simulated, the body on a "
                  "free root, held by its grasps and footholds and moved by motors within their torque limits "
                  "(docs/PHYSICS.md, &ldquo;Performed in MuJoCo&rdquo;). The arrows are the forces from the holds; "
                  "a red ball marks where a failed move&apos;s limb was when it failed.</p>\n",
                  xml_escaped(p.folder));
    if (!p.moves.empty()) {
      out_ +=
          "<table class=\"numbers\">\n<thead><tr><th>move</th><th>limb</th><th>hold</th><th>outcome</th>"
          "<th>largest torque / limit</th></tr></thead>\n<tbody>\n";
      for (std::size_t k = 0; k < p.moves.size(); ++k) {
        const PerformedMoveRow& move = p.moves[k];
        append_format(out_, "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.2f}</td></tr>\n", k + 1,
                      xml_escaped(move.limb), move.hold_id,
                      move.performed ? std::string("performed") : "failed: " + xml_escaped(move.cause),
                      move.max_torque_ratio);
      }
      out_ += "</tbody>\n</table>\n";
    }
    if (!p.replay.is_null()) out_ += "<div id=\"crux-performed\"></div>\n";
    out_ += "</section>\n";
  }

  const ReportPage& page_;
  std::string out_;
};

}  // namespace

std::string html_report(const ReportPage& page) { return Page(page).render(); }

}  // namespace crux
