#include "wall/wall_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "common/atomic_file.hpp"
#include "common/counted.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "common/json_field.hpp"
#include "common/printable.hpp"
#include "wall/incline.hpp"

namespace crux {
namespace {

using Json = OrderedJson;

constexpr std::array<std::string_view, 6> kTopLevelKeys{"format", "version", "name", "finish_height", "start", "holds"};
constexpr std::array<std::string_view, 7> kTopLevelKeysV2{"format",  "version", "name", "finish_height",
                                                          "incline", "start",   "holds"};
constexpr std::array<std::string_view, 3> kHoldKeys{"id", "position", "radius"};
constexpr std::array<std::string_view, 4> kHoldKeysV2{"id", "position", "radius", "support"};
constexpr std::size_t kMinimumHoldCount = kLimbCount;

// nlohmann's error id for a number too large for a double (e.g. 1e999).
constexpr int kNumberOverflowError = 406;

// A JSON string literal, escaped, so that keys and values quoted in a message can
// never break it over several lines.
std::string json_quoted(std::string_view text) { return Json(text).dump(); }

std::string location(const std::string& path) { return path.empty() ? "at the top level" : "in " + path; }

// Text quoted from the input, as it may go into a one-line message: at most 200 bytes,
// control characters escaped.
std::string shortened(std::string text) {
  constexpr std::size_t kMaxQuotedBytes = 200;
  if (text.size() > kMaxQuotedBytes) text = text.substr(0, kMaxQuotedBytes) + "...";
  return printable(text);
}

// "parse error at line 3, column 7: syntax error while parsing value - invalid
// literal; ..." -> "JSON syntax error at line 3, column 7: invalid literal; ...".
// Plain string search, not std::regex, whose matcher recurses once per character and
// overflows the stack on a long message; the parser quotes the text it last read, so
// the problem is cut short and its control characters escaped to stay one line.
std::string syntax_problem(const std::string& parser_message) {
  const auto number_at = [&](std::size_t& at) {
    const std::size_t begin = at;
    while (at < parser_message.size() && std::isdigit(static_cast<unsigned char>(parser_message[at]))) ++at;
    return parser_message.substr(begin, at - begin);
  };
  std::size_t at = parser_message.find("at line ");
  if (at == std::string::npos) return "JSON syntax error: " + shortened(parser_message);
  at += 8;
  const std::string line = number_at(at);
  if (line.empty() || parser_message.compare(at, 9, ", column ") != 0)
    return "JSON syntax error: " + shortened(parser_message);
  at += 9;
  const std::string column = number_at(at);
  if (column.empty() || parser_message.compare(at, 2, ": ") != 0)
    return "JSON syntax error: " + shortened(parser_message);
  at += 2;
  std::string problem = parser_message.substr(at);
  constexpr std::string_view kWhileParsing = "syntax error while parsing ";
  if (problem.rfind(kWhileParsing, 0) == 0) {
    if (const std::size_t dash = problem.find(" - "); dash != std::string::npos) problem = problem.substr(dash + 3);
  }
  return fmt::format("JSON syntax error at line {}, column {}: {}", line, column, shortened(problem));
}

// First pass over the text, before building the document: the DOM parser keeps the
// last of duplicate keys silently and reports an overflowing number (1e999) without
// its position, so this pass tracks where it is in the document to name both.
class JsonStructureCheck final : public Json::json_sax_t {
 public:
  const std::string& problem() const { return problem_; }

  bool null() override { return value_done(); }
  bool boolean(bool) override { return value_done(); }
  bool number_integer(number_integer_t) override { return value_done(); }
  bool number_unsigned(number_unsigned_t) override { return value_done(); }
  bool number_float(number_float_t, const string_t&) override { return value_done(); }
  bool string(string_t&) override { return value_done(); }
  bool binary(binary_t&) override { return value_done(); }

  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& key) override {
    Frame& object = frames_.back();
    if (!object.keys.insert(key).second) {
      problem_ = fmt::format("duplicate key {} {}", json_quoted(key), location(path(frames_.size() - 1)));
      return false;
    }
    object.key = key;
    return true;
  }
  bool end_object() override { return container_done(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return container_done(); }

  bool parse_error(std::size_t, const std::string& last_token, const Json::exception& error) override {
    if (error.id == kNumberOverflowError) {
      const std::string where = path(frames_.size());
      problem_ = fmt::format("{} is not finite ({} overflows a double)", where.empty() ? "the value" : where,
                             shortened(last_token));
    } else {
      problem_ = syntax_problem(error.what());
    }
    return false;
  }

 private:
  struct Frame {
    bool is_array = false;
    std::size_t index = 0;  // arrays: the element being read
    std::string key;        // objects: the member being read
    std::set<std::string> keys;
  };

  // The path ("holds[2].position[1]") of the value being read in frames_[depth - 1].
  std::string path(std::size_t depth) const {
    std::string text;
    for (std::size_t i = 0; i < depth; ++i) {
      text =
          frames_[i].is_array ? fmt::format("{}[{}]", text, frames_[i].index) : json_child_path(text, frames_[i].key);
    }
    return text;
  }
  bool open(bool is_array) {
    frames_.emplace_back().is_array = is_array;
    return true;
  }
  bool value_done() {
    if (!frames_.empty() && frames_.back().is_array) ++frames_.back().index;
    return true;
  }
  bool container_done() {
    frames_.pop_back();
    return value_done();
  }

  std::vector<Frame> frames_;
  std::string problem_;
};

// Second pass: the document's meaning. Paths in messages follow the file
// ("holds[3].radius"); hold indices are 0-based, as in the file's array.
class WallReader {
 public:
  explicit WallReader(const std::string& source) : source_(source) {}

  Wall read(const Json& root) {
    if (!root.is_object()) fail("the top level must be a JSON object, got " + json_value_description(root));
    check_format(root);
    version_ = check_version(root);
    if (version_ == 1) {
      reject_unknown_keys(root, "", kTopLevelKeys);
    } else {
      reject_unknown_keys(root, "", kTopLevelKeysV2);
    }
    Wall wall;
    wall.name = text(root, "", "name");
    wall.finish_height = number(root, "", "finish_height");
    if (root.contains("incline")) {
      wall.incline_deg = number(root, "", "incline");
      if (!(std::abs(wall.incline_deg) < kMaxInclineDeg)) {
        fail(
            fmt::format("incline is {} degrees; it must be between -90 and 90 (exclusive): 0 is vertical, > 0 "
                        "overhanging",
                        wall.incline_deg));
      }
    }
    wall.holds = holds(field(root, "", "holds"));
    wall.start = start(field(root, "", "start"), wall);
    return wall;
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const { throw InputError(source_, problem); }

  void check_format(const Json& root) const {
    const auto format = root.find("format");
    if (format == root.end())
      fail(fmt::format("format is missing; a wall file has \"format\": {}", json_quoted(kWallFormatName)));
    if (*format != kWallFormatName)
      fail(fmt::format("format must be {}, got {}", json_quoted(kWallFormatName), format->dump()));
  }

  int check_version(const Json& root) const {
    const auto version = root.find("version");
    if (version == root.end()) fail("version is missing (supported versions: 1, 2)");
    if (!version->is_number_integer()) fail("version must be an integer, got " + json_value_description(*version));
    if (*version != 1 && *version != 2) {
      fail(fmt::format("version {} is not supported (supported versions: 1, 2)", version->dump()));
    }
    return version->get<int>();
  }

  template <std::size_t N>
  void reject_unknown_keys(const Json& object, const std::string& path,
                           const std::array<std::string_view, N>& allowed) const {
    for (const auto& [key, value] : object.items()) {
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        const bool newer = version_ == 1 && (key == "incline" || key == "support");
        fail(fmt::format("unknown key {} {} (allowed: {}){}", json_quoted(key), location(path),
                         fmt::join(allowed, ", "), newer ? "; it needs \"version\": 2" : ""));
      }
    }
  }

  const Json& field(const Json& object, const std::string& path, std::string_view key) const {
    return JsonField(source_, object, path)[key].json();
  }

  std::string text(const Json& object, const std::string& path, std::string_view key) const {
    return JsonField(source_, object, path)[key].string();
  }

  // Finite: the structure check has already rejected numbers that overflow a double,
  // and JSON has no literal for NaN or infinity.
  double number(const Json& object, const std::string& path, std::string_view key) const {
    return JsonField(source_, object, path)[key].number();
  }

  int hold_id(const Json& value, const std::string& path) const {
    const bool positive = value.is_number_unsigned() ? value.get<std::uint64_t>() > 0
                                                     : value.is_number_integer() && value.get<std::int64_t>() > 0;
    if (!positive) fail(fmt::format("{} must be a positive integer, got {}", path, json_value_description(value)));
    constexpr auto kLargestId = static_cast<std::uint64_t>(std::numeric_limits<int>::max());
    if (value.get<std::uint64_t>() > kLargestId) {
      fail(fmt::format("{} is {}, larger than the largest supported hold id {}", path, value.dump(), kLargestId));
    }
    return value.get<int>();
  }

  Eigen::Vector3d position(const Json& value, const std::string& path) const {
    if (!value.is_array())
      fail(fmt::format("{} must be an array of 3 numbers [x, y, z], got {}", path, json_value_description(value)));
    if (value.size() != 3) fail(fmt::format("{} must have 3 coordinates [x, y, z], got {}", path, value.size()));
    Eigen::Vector3d result;
    for (int axis = 0; axis < 3; ++axis) {
      const Json& coordinate = value[axis];
      if (!coordinate.is_number()) {
        fail(fmt::format("{}[{}] must be a number, got {}", path, axis, json_value_description(coordinate)));
      }
      result[axis] = coordinate.get<double>();
    }
    return result;
  }

  Eigen::Vector3d support(const Json& value, const std::string& path) const {
    const Eigen::Vector3d direction = position(value, path);
    const double length = direction.norm();
    // A direction needs a length to normalise; far below any hold's size is a typo.
    if (!(length > 1e-9) || !std::isfinite(length)) {
      fail(fmt::format("{} must be a direction [x, y, z] of non-zero length, got {}", path, value.dump()));
    }
    return direction / length;
  }

  Hold hold(const Json& value, const std::string& path) const {
    JsonField(source_, value, path).expect_object();
    if (version_ == 1) {
      reject_unknown_keys(value, path, kHoldKeys);
    } else {
      reject_unknown_keys(value, path, kHoldKeysV2);
    }
    Hold result;
    result.id = hold_id(field(value, path, "id"), path + ".id");
    result.position = position(field(value, path, "position"), path + ".position");
    result.radius = number(value, path, "radius");
    if (!(result.radius > 0.0))
      fail(fmt::format("{}.radius must be positive, got {}", path, Json(result.radius).dump()));
    if (value.contains("support")) result.support = support(value["support"], path + ".support");
    return result;
  }

  std::vector<Hold> holds(const Json& value) const {
    if (!value.is_array()) fail("holds must be an array, got " + json_value_description(value));
    if (value.size() < kMinimumHoldCount) {
      fail(fmt::format("holds has {}; a wall needs at least {} holds (one per limb)",
                       counted(value.size(), "entry", "entries"), kMinimumHoldCount));
    }
    if (value.size() > static_cast<std::size_t>(kMaxHoldCount)) {
      fail(fmt::format("holds has {} entries; crux supports at most {} holds on a wall", value.size(), kMaxHoldCount));
    }
    std::vector<Hold> result;
    std::unordered_map<int, std::size_t> index_of_id;
    for (std::size_t i = 0; i < value.size(); ++i) {
      result.push_back(hold(value[i], fmt::format("holds[{}]", i)));
      const auto [first, inserted] = index_of_id.emplace(result.back().id, i);
      if (!inserted)
        fail(fmt::format("duplicate hold id {} (holds[{}] and holds[{}])", result.back().id, first->second, i));
    }
    return result;
  }

  std::array<int, kLimbCount> start(const Json& value, const Wall& wall) const {
    JsonField(source_, value, "start").expect_object();
    std::array<std::string_view, kLimbCount> limbs;
    for (int limb = 0; limb < kLimbCount; ++limb) limbs[limb] = enum_name(static_cast<Limb>(limb));
    reject_unknown_keys(value, "start", limbs);
    std::array<int, kLimbCount> indices{};
    for (int limb = 0; limb < kLimbCount; ++limb) {
      const std::string path = json_child_path("start", limbs[limb]);
      const int id = hold_id(field(value, "start", limbs[limb]), path);
      indices[limb] = wall.index_of(id);
      if (indices[limb] < 0) fail(fmt::format("{} names hold {}, which is not in holds", path, id));
      for (int earlier = 0; earlier < limb; ++earlier) {
        if (indices[earlier] == indices[limb]) {
          fail(
              fmt::format("start.{} and {} both name hold {}; each limb needs its own hold", limbs[earlier], path, id));
        }
      }
    }
    return indices;
  }

  const std::string& source_;
  int version_ = 1;
};

std::string number_text(double value) { return Json(value).dump(); }

std::string hold_line(const Hold& hold) {
  const std::string support = hold.support ? fmt::format(R"(, "support": [{}, {}, {}])", number_text(hold.support->x()),
                                                         number_text(hold.support->y()), number_text(hold.support->z()))
                                           : "";
  return fmt::format(R"(    {{"id": {}, "position": [{}, {}, {}], "radius": {}{}}})", hold.id,
                     number_text(hold.position.x()), number_text(hold.position.y()), number_text(hold.position.z()),
                     number_text(hold.radius), support);
}

// Version 1 for a wall that needs nothing of version 2, so that its file keeps its bytes.
bool needs_version_2(const Wall& wall) {
  return wall.incline_deg != 0.0 ||
         std::any_of(wall.holds.begin(), wall.holds.end(), [](const Hold& h) { return h.support.has_value(); });
}

std::string start_line(const Wall& wall) {
  std::vector<std::string> members;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    members.push_back(
        fmt::format("{}: {}", json_quoted(enum_name(static_cast<Limb>(limb))), wall.holds.at(wall.start[limb]).id));
  }
  return fmt::format("  \"start\": {{{}}},\n", fmt::join(members, ", "));
}

}  // namespace

Wall parse_wall(const std::string& json_text, const std::string& source) {
  if (json_text.find_first_not_of(" \t\r\n") == std::string::npos) throw InputError(source, "the file is empty");
  // The parser ends the text at a NUL byte, so what follows it would be ignored (as the URDF reader refuses it).
  if (const std::size_t nul = json_text.find('\0'); nul != std::string::npos) {
    throw InputError(source, fmt::format("a NUL byte at offset {}: a wall file is JSON text", nul));
  }
  JsonStructureCheck check;
  if (!Json::sax_parse(json_text, &check)) throw InputError(source, check.problem());
  return WallReader(source).read(Json::parse(json_text));
}

Wall load_wall(const std::string& path) { return parse_wall(read_input_file(path, "wall file"), path); }

std::string wall_to_json(const Wall& wall) {
  std::vector<std::string> holds;
  for (const Hold& hold : wall.holds) holds.push_back(hold_line(hold));
  const bool version_2 = needs_version_2(wall);
  const std::string incline = version_2 ? fmt::format("  \"incline\": {},\n", number_text(wall.incline_deg)) : "";
  return fmt::format(
      "{{\n  \"format\": {},\n  \"version\": {},\n  \"name\": {},\n  \"finish_height\": {},\n{}{}"
      "  \"holds\": [\n{}\n  ]\n}}\n",
      json_quoted(kWallFormatName), version_2 ? 2 : 1, json_quoted(wall.name), number_text(wall.finish_height), incline,
      start_line(wall), fmt::join(holds, ",\n"));
}

void save_wall(const std::string& path, const Wall& wall) {
  const std::string text = wall_to_json(wall);
  try {
    parse_wall(text, "");
  } catch (const InputError& problem) {
    throw InputError(path, std::string("not written, the wall would not load back: ") + problem.what());
  }
  write_file_atomically(path, text);
}

}  // namespace crux
