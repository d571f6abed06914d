#include "outputs/trajectory_csv.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "common/csv_rows.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "outputs/posture_csv.hpp"

namespace crux {
namespace {

// The columns between the sample index and the joints, as the writer names them.
std::vector<std::string> sample_columns() {
  std::vector<std::string> names{"time_s", "move", "root_qw", "root_qx", "root_qy", "root_qz"};
  for (int limb = 0; limb < kLimbCount; ++limb) {
    for (const char* axis : {"x", "y", "z"})
      names.push_back(fmt::format("{}_f{}_n", enum_name(static_cast<Limb>(limb)), axis));
  }
  return names;
}

constexpr std::size_t kForceColumn = 6;

// A row's sample, checked as far as a drawing needs: a root near its wall and joint angles
// within a turn of their limits (MuJoCo's joint limits are soft, so a simulated angle may
// pass its limit a little).
TrajectorySample read_sample(const BodyModel& model, std::span<const std::string_view> cells, std::size_t line,
                             const std::string& file) {
  TrajectorySample sample;
  std::size_t c = 1;
  const auto number = [&] { return csv_number(cells[c++], file, line); };
  sample.time = number();
  sample.move = csv_integer(cells[c++], file, line);
  if (sample.move < -1)
    throw InputError(file, fmt::format("line {}: move {} is not a move (-1 is the start)", line, sample.move));
  const double w = number(), x = number(), y = number(), z = number();
  sample.root_orientation = Eigen::Quaterniond(w, x, y, z);
  if (std::abs(sample.root_orientation.norm() - 1.0) > 1e-6) {
    throw InputError(file, fmt::format("line {}: the root's rotation is not a unit quaternion", line));
  }
  for (Eigen::Vector3d& force : sample.hold_forces) {
    for (int axis = 0; axis < 3; ++axis) force[axis] = number();
  }
  constexpr double kRootLimit = 1000, kAngleSlack = 2 * std::numbers::pi;
  for (int k = 0; k < kConfigurationDof; ++k) {
    const double value = number();
    const bool root = k < kRootDof;
    if (root ? std::abs(value) > kRootLimit
             : value < model.lower_limits[k] - kAngleSlack || value > model.upper_limits[k] + kAngleSlack) {
      throw InputError(file, fmt::format("line {}: {} = {} is outside {}", line, model.joints[k].name, value,
                                         root ? "[-1000, 1000] m" : "a turn of the joint's limits"));
    }
    sample.posture[k] = value;
  }
  return sample;
}

}  // namespace

std::string trajectory_csv(const BodyModel& model, std::span<const TrajectorySample> samples) {
  std::vector<PostureCsvColumn> columns;
  for (std::string& name : sample_columns()) columns.push_back({std::move(name), {}});
  std::vector<Posture> postures;
  for (const TrajectorySample& sample : samples) {
    const Eigen::Quaterniond& q = sample.root_orientation;
    const double values[] = {sample.time, static_cast<double>(sample.move), q.w(), q.x(), q.y(), q.z()};
    for (std::size_t c = 0; c < std::size(values); ++c) columns[c].cells.push_back(fmt::format("{}", values[c]));
    for (int limb = 0; limb < kLimbCount; ++limb) {
      for (int axis = 0; axis < 3; ++axis) {
        columns[kForceColumn + 3 * limb + axis].cells.push_back(fmt::format("{}", sample.hold_forces[limb][axis]));
      }
    }
    postures.push_back(sample.posture);
  }
  return posture_csv(model, postures, "sample", columns);
}

std::vector<TrajectorySample> read_trajectory_csv(const BodyModel& model, const std::filesystem::path& file) {
  const std::string name = file.string();
  const std::string text = read_input_file(name, "trajectory file");
  std::string header = "sample";
  for (const std::string& column : sample_columns()) header += "," + column;
  for (const BodyJoint& joint : model.joints) header += "," + joint.name;
  const std::vector<std::string_view> rows = csv_rows(text, name, header);
  const std::size_t columns = 1 + sample_columns().size() + kConfigurationDof;
  std::vector<TrajectorySample> samples;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::size_t line = csv_line_number(i);
    const std::vector<std::string_view> cells = csv_cells(rows[i], i, columns, name);
    if (csv_integer(cells[0], name, line) != static_cast<int>(i)) {
      throw InputError(name, fmt::format("line {}: samples must be numbered from 0 in order", line));
    }
    TrajectorySample sample = read_sample(model, cells, line, name);
    if (!samples.empty() && (sample.time < samples.back().time || sample.move < samples.back().move)) {
      throw InputError(name, fmt::format("line {}: a sample before the one above it in time or in move", line));
    }
    samples.push_back(std::move(sample));
  }
  return samples;
}

}  // namespace crux
