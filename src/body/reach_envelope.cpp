#include "body/reach_envelope.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "body/body_data.hpp"
#include "body/kinematics.hpp"

namespace crux {

ReachEnvelope compute_reach_envelope(const BodyModel& model) {
  BodyData data(model);
  forward_kinematics(model, data, Posture::Zero());
  ReachEnvelope envelope;
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const AttachedPoint& grasp = model.grasp_points[limb];
    std::vector<int> chain;  // grasp joint back to the first joint past the root
    for (int joint = grasp.joint; joint >= kRootDof; joint = model.joints[joint].parent) chain.push_back(joint);
    double radius = grasp.offset.norm();
    if (chain.empty()) {
      // The grasp frame rides on the root: it keeps a fixed offset.
      envelope.chain_base[limb] = data.points[operational_point(limb)] - data.points[0];
    } else {
      // The first joint's origin follows the root's translation only; every later origin
      // and the grasp point sit at fixed distances along rotated links.
      envelope.chain_base[limb] = data.placements[chain.back()].origin - data.points[0];
      for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
        const BodyJoint& joint = model.joints[chain[k]];
        radius += joint.origin_translation.norm();
      }
      // A sliding joint, or a chain hanging off an intermediate root axis, has no such bound.
      const bool bounded = model.joints[chain.back()].parent == kRootDof - 1 &&
                           std::none_of(chain.begin(), chain.end(), [&](int joint) { return model.joints[joint].prismatic; });
      if (!bounded) radius = std::numeric_limits<double>::infinity();
    }
    envelope.radius[limb] = radius;
  }
  return envelope;
}

}  // namespace crux
