#include "body/reach_envelope.hpp"

#include <algorithm>
#include <vector>

#include "body/body_data.hpp"
#include "body/kinematics.hpp"

namespace crux {

ReachEnvelope compute_reach_envelope(const BodyModel& model) {
  BodyData data(model);
  forward_kinematics(model, data, Posture::Zero());
  ReachEnvelope envelope;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    // The limb's chain from the root to its grasp joint, past the three root axes.
    const std::vector<int>& chain = model.chains[operational_point(limb)];
    const auto first = std::find_if(chain.begin(), chain.end(), [](int joint) { return joint >= kRootDof; });
    double radius = model.grasp_points[limb].offset.norm();
    if (first == chain.end()) {
      // The grasp frame rides on the root: a fixed offset if on its last axis, which
      // carries the root point; on an earlier axis it lags the later translations.
      envelope.chain_base[limb] = data.points[operational_point(limb)] - data.points[0];
      radius = model.grasp_points[limb].joint == kRootDof - 1 ? 0.0 : ReachEnvelope::kUnbounded;
    } else {
      // The first joint's origin follows the root's translation only; every later origin
      // and the grasp point sit at fixed distances along rotated links.
      envelope.chain_base[limb] = data.placements[*first].origin - data.points[0];
      for (auto joint = first + 1; joint != chain.end(); ++joint)
        radius += model.joints[*joint].origin_translation.norm();
      // A sliding joint, or a chain hanging off an intermediate root axis, has no such bound.
      const bool bounded = model.joints[*first].parent == kRootDof - 1 &&
                           std::none_of(first, chain.end(), [&](int joint) { return model.joints[joint].prismatic; });
      if (!bounded) radius = ReachEnvelope::kUnbounded;
    }
    envelope.radius[limb] = radius;
  }
  return envelope;
}

}  // namespace crux
