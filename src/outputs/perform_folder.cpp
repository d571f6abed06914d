#include "outputs/perform_folder.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "common/input_error.hpp"
#include "common/json_field.hpp"
#include "common/printable.hpp"
#include "outputs/trajectory_csv.hpp"
#include "wall/wall_file.hpp"

namespace crux {
namespace fs = std::filesystem;

namespace {

template <typename Enum>
Enum named(const JsonField& field) {
  const std::optional<Enum> value = parse_enum<Enum>(field.string());
  if (!value) {
    field.fail(
        fmt::format("{} is {}, not a name crux writes there", field.path(), printable(field.string().substr(0, 40))));
  }
  return *value;
}

// A failure's cause: null for none.
MoveFailure cause(const JsonField& field) { return field.is_null() ? MoveFailure::None : named<MoveFailure>(field); }

AttemptedMove attempted_move(const JsonField& field, const Wall& wall) {
  AttemptedMove move;
  move.limb = named<Limb>(field["limb"]);
  const int id = field["hold"].integer();
  move.hold = wall.index_of(id);
  if (move.hold < 0) field.fail(fmt::format("{}.hold names hold {}, which wall.json does not have", field.path(), id));
  move.performed = field["performed"].boolean();
  move.cause = cause(field["cause"]);
  if (move.performed != (move.cause == MoveFailure::None)) {
    field.fail(field.path() + ".cause must be null exactly when performed");
  }
  move.max_torque_ratio = field["max_torque_ratio"].number();
  return move;
}

void read_record(PerformFolder& folder) {
  const std::string file = (folder.directory / "perform.json").string();
  const OrderedJson json = read_json_file(file, "perform file");
  const JsonField record(file, json);
  record.expect_object();
  folder.climb = record["climb"].string();
  folder.physics = record["physics_model"].string();
  folder.found = record["found"].boolean();
  // Without a plan nothing was performed: no length (-1), no start, no moves.
  const int length = record["length"].integer(-1);
  if ((length >= 0) != folder.found) record.fail("length must be -1 exactly when found is false");
  folder.planned_moves = std::max(length, 0);
  const JsonField start = record["start"];
  if (start.is_null() == folder.found) record.fail("start must be null exactly when found is false");
  if (!start.is_null()) {
    folder.start_held = start["performed"].boolean();
    folder.start_cause = cause(start["cause"]);
  }
  const JsonField moves = record["moves"];
  for (std::size_t k = 0; k < moves.size(); ++k) {
    folder.moves.push_back(attempted_move(moves[k], folder.wall));
    if (k + 1 < moves.size() && !folder.moves.back().performed) {
      moves.fail(fmt::format("moves[{}] failed, so it must be the climb's last move", k));
    }
  }
  if (folder.moves.size() > static_cast<std::size_t>(folder.planned_moves)) {
    moves.fail(fmt::format("moves has {} moves, more than the climb's length {}", moves.size(), folder.planned_moves));
  }
  folder.reached_top = record["reached_top"].boolean();
  // Once the start held, the moves go on until one fails or the last is performed.
  const bool all_performed = folder.start_held &&
                             folder.moves.size() == static_cast<std::size_t>(folder.planned_moves) &&
                             (folder.moves.empty() || folder.moves.back().performed);
  const bool one_failed = folder.start_held && !folder.moves.empty() && !folder.moves.back().performed;
  if (folder.reached_top != (folder.found && all_performed) ||
      (folder.start_held && !folder.reached_top && !one_failed) || (!folder.start_held && !folder.moves.empty())) {
    record.fail("reached_top, start and moves disagree: the moves go on from a start that held until one fails");
  }
  folder.max_torque_ratio = record["max_torque_ratio"].number();
  folder.simulated_s = record["simulated_s"].number();
}

}  // namespace

const TrajectorySample& PerformFolder::step_sample(int step) const {
  std::size_t found = 0;
  for (std::size_t i = 0; i < trajectory.size() && trajectory[i].move < step; ++i) found = i;
  return trajectory.at(found);
}

bool is_perform_folder(const fs::path& directory) {
  std::error_code error;
  return fs::is_regular_file(directory / "perform.json", error);
}

PerformFolder read_perform_folder(const fs::path& directory, const BodyModel& model) {
  PerformFolder folder;
  folder.directory = directory;
  folder.wall = load_wall((directory / "wall.json").string());
  read_record(folder);
  folder.trajectory = read_trajectory_csv(model, directory / "trajectory.csv");
  return folder;
}

}  // namespace crux
