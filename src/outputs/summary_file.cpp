#include "outputs/summary_file.hpp"

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "common/printable.hpp"

namespace crux {
namespace {

constexpr const char* kSummaryFormat = "crux-summary";
// Version 4 dropped the run time and added provenance.produced_by, neither of which is
// read here: both read alike.
constexpr int kOldestSummaryVersion = 3, kSummaryVersion = 4;

TransferMetricData transfer_metric(const JsonField& metric, const std::string& name) {
  TransferMetricData out;
  out.name = name;
  out.description = metric["description"].string();
  out.higher_is_better = metric["higher_is_better"].boolean();
  out.control_mean = metric["control"]["mean"].number();
  const JsonField difference = metric["transfer_minus_control"];
  out.difference = difference["mean"].number();
  const JsonField interval = difference["ci95_t_over_walls"];
  if (!interval.is_null()) {
    interval.expect_size(2);
    out.difference_ci95 = std::array<double, 2>{interval[0].number(), interval[1].number()};
  }
  out.p_value = difference["p_value"].number();
  out.walls = difference["walls"].integer(0);
  return out;
}

}  // namespace

OrderedJson read_summary(const std::filesystem::path& folder) {
  const std::string file = (folder / "summary.json").string();
  const std::string text = read_input_file(file, "summary file");
  OrderedJson json;
  try {
    json = OrderedJson::parse(text);
  } catch (const OrderedJson::exception& e) {
    throw InputError(file, "not JSON: " + printable(e.what()));
  }
  const JsonField summary(file, json);
  summary.expect_object();
  if (!summary.contains("format") || json["format"] != kSummaryFormat) {
    summary.fail(fmt::format("not a crux summary: format is {}, not \"{}\"",
                             summary.contains("format") ? printable(json["format"].dump().substr(0, 40)) : "missing",
                             kSummaryFormat));
  }
  if (const int version = summary["version"].integer(); version < kOldestSummaryVersion || version > kSummaryVersion) {
    summary.fail(fmt::format("version {} is not one of the versions {} to {} this crux reads; write the folder again",
                             version, kOldestSummaryVersion, kSummaryVersion));
  }
  return json;
}

int summary_seeds_per_wall(const OrderedJson& summary, const std::string& file) {
  return JsonField(file, summary)["seeds_per_wall"].integer(1, 1'000'000);
}

int summary_iterations(const OrderedJson& summary, const std::string& file) {
  return JsonField(file, summary)["iterations"].integer(0);
}

std::string summary_kind(const OrderedJson& summary, const std::string& file) {
  const JsonField kind = JsonField(file, summary)["kind"];
  const std::string value = kind.string();
  if (value != "experiment" && value != "run") {
    kind.fail(fmt::format("kind is \"{}\", not \"experiment\" or \"run\"", printable(value.substr(0, 40))));
  }
  return value;
}

std::string summary_urdf(const OrderedJson& summary) {
  if (const auto provenance = summary.find("provenance"); provenance != summary.end() && provenance->is_object()) {
    if (const auto urdf = provenance->find("urdf"); urdf != provenance->end() && urdf->is_string()) {
      return urdf->get<std::string>();
    }
  }
  return "";
}

void read_paper_summary(const std::filesystem::path& folder, PaperFigureData& data) {
  const std::string file = (folder / "summary.json").string();
  const OrderedJson json = read_summary(folder);
  const JsonField summary(file, json);
  data.iterations = summary_iterations(json, file);
  data.seeds_per_wall = summary_seeds_per_wall(json, file);

  const JsonField lengths = summary["episode_lengths"];
  lengths.expect_object();
  for (const Condition condition : kConditions) {
    const std::string name = condition_name(condition);
    if (!lengths.contains(name)) continue;
    PaperConditionData c;
    c.condition = condition;
    const JsonField run_lengths = lengths[name];
    const JsonField facts = summary["run_facts"][name];
    facts.expect_size(run_lengths.size());
    for (std::size_t i = 0; i < run_lengths.size(); ++i) {
      PaperRunData run;
      run.wall_pair = facts[i]["wall_pair"].integer(0);
      run.plan_length = facts[i]["plan_length"].integer(-1);
      const JsonField episodes = run_lengths[i];
      for (std::size_t e = 0; e < episodes.size(); ++e) run.episode_lengths.push_back(episodes[e].integer(1));
      c.runs.push_back(std::move(run));
    }
    for (int l = 0; l < kLimbCount; ++l) {
      const JsonField map = summary["qgrid_maps"][name][enum_name(static_cast<Limb>(l))];
      map.expect_size(static_cast<std::size_t>(data.grid.tile_count()));
      for (std::size_t t = 0; t < map.size(); ++t) c.q_grid_maps[l].push_back(map[t].number());
    }
    data.conditions.push_back(std::move(c));
  }
  if (data.conditions.empty()) summary.fail("episode_lengths holds none of training, transfer, control");

  const JsonField metrics = summary["transfer_vs_control"];
  metrics.expect_object();
  for (const auto& [name, value] : json["transfer_vs_control"].items()) {
    data.transfer_metrics.push_back(transfer_metric(metrics[name], name));
  }
}

}  // namespace crux
