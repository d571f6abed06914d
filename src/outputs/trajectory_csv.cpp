#include "outputs/trajectory_csv.hpp"

#include <fmt/format.h>

#include "outputs/posture_csv.hpp"

namespace crux {

std::string trajectory_csv(const BodyModel& model, std::span<const TrajectorySample> samples) {
  std::vector<PostureCsvColumn> columns{{"time_s", {}},  {"move", {}},    {"root_qw", {}},
                                        {"root_qx", {}}, {"root_qy", {}}, {"root_qz", {}}};
  for (int limb = 0; limb < kLimbCount; ++limb) {
    for (const char* axis : {"x", "y", "z"}) {
      columns.push_back({fmt::format("{}_f{}_n", enum_name(static_cast<Limb>(limb)), axis), {}});
    }
  }
  std::vector<Posture> postures;
  for (const TrajectorySample& sample : samples) {
    const Eigen::Quaterniond& q = sample.root_orientation;
    const double values[] = {sample.time, static_cast<double>(sample.move), q.w(), q.x(), q.y(), q.z()};
    for (std::size_t c = 0; c < std::size(values); ++c) columns[c].cells.push_back(fmt::format("{}", values[c]));
    for (int limb = 0; limb < kLimbCount; ++limb) {
      for (int axis = 0; axis < 3; ++axis) {
        columns[6 + 3 * limb + axis].cells.push_back(fmt::format("{}", sample.hold_forces[limb][axis]));
      }
    }
    postures.push_back(sample.posture);
  }
  return posture_csv(model, postures, "sample", columns);
}

}  // namespace crux
