#pragma once
// One climber simulated on one wall (docs/PHYSICS.md, "Performed in MuJoCo"): the MJCF
// compiled into a MuJoCo model of its own (a grasp writes the model), the data it steps,
// where crux's coordinates are in them, each servo's gains and each hand's grasp. One per
// thread, as BodyData.

#include <array>
#include <string>

#include "configurations/hold_configuration.hpp"
#include "physics/physics_model.hpp"
#include "simulation/footing.hpp"
#include "simulation/grasp.hpp"
#include "simulation/joint_servo.hpp"
#include "simulation/mujoco_layout.hpp"
#include "simulation/mujoco_model.hpp"
#include "wall/wall.hpp"

namespace crux {

class SimulatedClimber {
 public:
  // The model of mjcf_text(model, wall, physics, limits, start, servo).
  SimulatedClimber(const BodyModel& model, const Wall& wall, const PhysicsParameters& physics,
                   const StrengthProfile& limits, const Posture& start, const ServoParameters& servo);
  ~SimulatedClimber();
  SimulatedClimber(const SimulatedClimber&) = delete;
  SimulatedClimber& operator=(const SimulatedClimber&) = delete;

  // At rest at `posture`, each limb that `holds` names taking its hold where its grasp
  // point is, the others free; time zero.
  void place(const Posture& posture, const HoldConfiguration& holds);

  const BodyModel& body() const { return body_; }
  const Wall& wall() const { return wall_; }
  const PhysicsParameters& physics() const { return physics_; }
  const StrengthProfile& limits() const { return limits_; }
  const std::string& mjcf() const { return mjcf_; }
  mjModel_* model() { return mujoco_.get(); }
  const mjModel_* model() const { return mujoco_.get(); }
  mjData_* data() { return data_; }
  const mjData_* data() const { return data_; }
  const MujocoLayout& layout() const { return layout_; }
  const ServoGain& gain(int coordinate) const { return gains_[coordinate]; }
  // The grasp of `hand` (a hand: std::invalid_argument for a foot).
  const Grasp& grasp(Limb hand) const;
  // The footing of `foot` (a foot: std::invalid_argument for a hand).
  const Footing& footing(Limb foot) const;
  // The limb takes hold `hold` where its grasp point is now: a hand's grasp, a foot's footing.
  void take(Limb limb, int hold);
  void release(Limb limb);
  // The force its hold exerts on `limb`, MuJoCo's world coordinates: a hand's grasp, a
  // foot's contacts with its footing (zero when it holds nothing).
  Eigen::Vector3d hold_force(Limb limb) const;
  int wall_geom() const { return wall_geom_; }

 private:
  const BodyModel& body_;
  const Wall& wall_;
  PhysicsParameters physics_;
  StrengthProfile limits_;
  std::string mjcf_;
  MujocoModel mujoco_;
  mjData_* data_;
  MujocoLayout layout_;
  std::array<ServoGain, kConfigurationDof> gains_{};
  std::array<Grasp, 2> grasps_;
  std::array<Footing, 2> footings_;
  int wall_geom_ = -1;
};

}  // namespace crux
