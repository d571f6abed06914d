#include "climbing/numeric_observation.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "body/kinematics.hpp"
#include "common/input_error.hpp"

namespace crux {

namespace {

void write_relative_point(const Eigen::Vector3d& point, const Eigen::Vector3d& origin, float* out) {
  for (int k = 0; k < 3; ++k) out[k] = static_cast<float>(point[k] - origin[k]);
}

// The free limb's shoulder or hip: where its chain leaves the root, which does not rotate.
Eigen::Vector3d limb_root(const BodyModel& model, const Posture& posture, Limb limb) {
  return posture.head<3>() + model.reach_envelope.chain_base[static_cast<int>(limb)];
}

void write_reach_features(const BodyModel& model, const NumericObservationInput& state, int max_candidates,
                          const NumericObservationRows& out) {
  const Limb free = state.configuration.free_limb();
  const Eigen::Vector3d root = limb_root(model, state.posture, free);
  const auto count = static_cast<int>(state.candidate_holds.size());
  for (int slot = 0; slot < max_candidates; ++slot) {
    float* row = out.candidate_reach + kReachFeatures * slot;
    out.candidate_failed[slot] = 0.0F;
    if (slot >= count) {
      std::fill_n(row, kReachFeatures, 0.0F);
      continue;
    }
    const int hold = state.candidate_holds[slot];
    const Eigen::Vector3d& candidate = state.wall.holds[hold].position;
    write_relative_point(candidate, root, row);
    row[3] = static_cast<float>((candidate - root).norm());
    int column = 4;
    for (int limb = 0; limb < kLimbCount; ++limb) {
      const int held = state.configuration.holds[limb];
      if (held == kFree) continue;
      row[column++] = static_cast<float>((candidate - state.wall.holds[held].position).norm());
    }
    if (std::find(state.failed_holds.begin(), state.failed_holds.end(), hold) != state.failed_holds.end()) {
      out.candidate_failed[slot] = 1.0F;
    }
  }
}

}  // namespace

void write_numeric_observation(const BodyModel& model, BodyData& data, const NumericObservationInput& state,
                               int max_candidates, const NumericObservationRows& out) {
  const auto count = static_cast<int>(state.candidate_holds.size());
  if (count > max_candidates) {
    throw InputError("max_candidates", fmt::format("the wall '{}' offers {} candidates, more than {}", state.wall.name,
                                                   count, max_candidates));
  }
  const Limb free = state.configuration.free_limb();
  forward_kinematics(model, data, state.posture);
  const Eigen::Vector3d grasp = data.points[operational_point(free)];

  for (int limb = 0; limb < kLimbCount; ++limb) {
    out.free_limb[limb] = limb == static_cast<int>(free) ? 1.0F : 0.0F;
    const int hold = state.configuration.holds[limb];
    if (hold == kFree) {
      std::fill_n(out.held + 3 * limb, 3, 0.0F);
    } else {
      write_relative_point(state.wall.holds[hold].position, grasp, out.held + 3 * limb);
    }
  }
  for (int slot = 0; slot < max_candidates; ++slot) {
    if (slot < count) {
      write_relative_point(state.wall.holds[state.candidate_holds[slot]].position, grasp, out.candidates + 3 * slot);
    } else {
      std::fill_n(out.candidates + 3 * slot, 3, 0.0F);
    }
    out.candidate_mask[slot] = slot < count ? 1.0F : 0.0F;
  }
  write_relative_point(state.posture.head<3>(), grasp, out.posture);
  for (int i = 3; i < kConfigurationDof; ++i) out.posture[i] = static_cast<float>(state.posture[i]);
  write_relative_point(state.centre_of_mass, grasp, out.centre_of_mass);
  const double bound = 2 * state.max_span_m;
  out.to_finish[0] = static_cast<float>(std::clamp(state.wall.finish_height - state.centre_of_mass.z(), -bound, bound));
  if (out.candidate_reach != nullptr) write_reach_features(model, state, max_candidates, out);
}

}  // namespace crux
