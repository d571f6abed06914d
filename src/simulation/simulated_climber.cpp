#include "simulation/simulated_climber.hpp"

#include <stdexcept>

#include <mujoco/mujoco.h>

#include "simulation/mjcf_model.hpp"
#include "wall/hold_support.hpp"

namespace crux {

SimulatedClimber::SimulatedClimber(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics,
                                   const StrengthProfile& limits, const Posture& start, const ServoParameters& servo)
    : body_(model),
      wall_(wall),
      physics_(physics),
      limits_(limits),
      mjcf_(mjcf_text(model, wall, physics, limits, start, servo)),
      mujoco_(mjcf_, wall.name),
      data_(mj_makeData(mujoco_.get())),
      layout_(mujoco_layout(model, mujoco_.get(), wall.incline_deg)),
      grasps_{Grasp(mujoco_.get(), mjcf_grasp_name(Limb::RightHand)),
              Grasp(mujoco_.get(), mjcf_grasp_name(Limb::LeftHand))},
      footings_{Footing(mujoco_.get(), Limb::RightFoot), Footing(mujoco_.get(), Limb::LeftFoot)},
      wall_geom_(mj_name2id(mujoco_.get(), mjOBJ_GEOM, "wall")) {
  for (int i = kRootDof; i < static_cast<int>(model.joints.size()); ++i)
    gains_[i] = servo_gain(limits.joints[i], servo);
}

SimulatedClimber::~SimulatedClimber() { mj_deleteData(data_); }

const Grasp& SimulatedClimber::grasp(Limb hand) const {
  if (!is_hand(hand)) throw std::invalid_argument("a foot does not grasp");
  return grasps_[static_cast<int>(hand)];
}

const Footing& SimulatedClimber::footing(Limb foot) const {
  if (is_hand(foot)) throw std::invalid_argument("a hand has no footing");
  return footings_[static_cast<int>(foot) - static_cast<int>(Limb::RightFoot)];
}

void SimulatedClimber::take(Limb limb, int hold) {
  const Eigen::Vector3d grasp_point = layout_.to_world * simulated_grasp_point(layout_, data_, limb);
  if (is_hand(limb)) {
    grasp(limb).take(mujoco_.get(), grasp_point);
  } else {
    footing(limb).take(data_, grasp_point,
                       layout_.to_world * support_direction(wall_.holds[hold], limb, physics_.support_angle_deg));
  }
}

void SimulatedClimber::release(Limb limb) {
  if (is_hand(limb)) {
    grasp(limb).release(mujoco_.get());
  } else {
    footing(limb).release(data_);
  }
}

Eigen::Vector3d SimulatedClimber::hold_force(Limb limb) const {
  const mjModel* model = mujoco_.get();
  if (is_hand(limb)) return grasp(limb).force(model, data_);
  // A foot's contacts with its footing, not with the wall.
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  const int body = layout_.limb_body[static_cast<int>(limb)];
  const int footing_body = footing(limb).body();
  for (int c = 0; c < data_->ncon; ++c) {
    const mjContact& contact = data_->contact[c];
    const int body1 = model->geom_bodyid[contact.geom1], body2 = model->geom_bodyid[contact.geom2];
    if (!((body1 == body && body2 == footing_body) || (body2 == body && body1 == footing_body))) continue;
    mjtNum local[6];
    mj_contactForce(model, data_, c, local);
    // The contact frame's rows are its normal and tangents; the force acts on geom2.
    const Eigen::Map<const Eigen::Matrix<mjtNum, 3, 3, Eigen::RowMajor>> frame(contact.frame);
    const Eigen::Vector3d on_geom2 = frame.transpose() * Eigen::Vector3d(local[0], local[1], local[2]);
    total += model->geom_bodyid[contact.geom2] == body ? on_geom2 : Eigen::Vector3d(-on_geom2);
  }
  return total;
}

void SimulatedClimber::place(const Posture& posture, const HoldConfiguration& holds) {
  place_at_rest(layout_, mujoco_.get(), data_, posture);
  for (int limb = 0; limb < kLimbCount; ++limb) {
    const int hold = holds.holds[limb];
    if (hold == kFree) {
      release(static_cast<Limb>(limb));
    } else {
      take(static_cast<Limb>(limb), hold);
    }
  }
  mj_forward(mujoco_.get(), data_);
}

}  // namespace crux
