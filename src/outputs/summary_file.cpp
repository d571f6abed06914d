#include "outputs/summary_file.hpp"

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "common/printable.hpp"

namespace crux {
namespace {

constexpr const char* kSummaryFormat = "crux-summary";
// Version 4 dropped the run time and added provenance.produced_by, neither of which is
// read here: both read alike.
constexpr int kOldestSummaryVersion = 3, kSummaryVersion = 4;

}  // namespace

OrderedJson read_summary(const std::filesystem::path& folder) {
  const std::string file = (folder / "summary.json").string();
  OrderedJson json = read_json_file(file, "summary file");
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

}  // namespace crux
