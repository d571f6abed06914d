#pragma once
// A hand's grasp of a hold in MuJoCo (docs/PHYSICS.md, "Performed in MuJoCo"): the model's
// equality constraint switched on with the hold as its anchor, its force read back each
// step, and the verdict on that force under the static model's limits, which decides when
// the hand lets go.

#include <string>

#include <Eigen/Core>

#include "common/enum_names.hpp"
#include "physics/contact_model.hpp"

struct mjModel_;
struct mjData_;

namespace crux {

// A grasp's force is within the hand's limits, or why not.
enum class GraspVerdict { Held, GripExceeded, OutsideFriction };
template <>
struct EnumNames<GraspVerdict> {
  static constexpr std::array<EnumName<GraspVerdict>, 3> entries{{{GraspVerdict::Held, "held"},
                                                                  {GraspVerdict::GripExceeded, "grip_exceeded"},
                                                                  {GraspVerdict::OutsideFriction, "outside_friction"}}};
};

// The hold's force on the hand against `contact` (world coordinates; normal_force_limit is
// the grip): beyond the grip first, else outside the friction pyramid, within `tolerance`
// newtons.
GraspVerdict grasp_verdict(const PointContact& contact, const Eigen::Vector3d& force, double tolerance);

// One hand's `connect` constraint (simulation/mjcf_model's mjcf_grasp_name) in a model.
class Grasp {
 public:
  // std::invalid_argument when the model has no equality constraint of that name: a
  // model crux did not write.
  Grasp(const mjModel_* model, const std::string& name);

  // Switches the constraint on, holding the hand's grasp point at `hold` (world
  // coordinates). It writes the model: each thread steps a copy of its own.
  void take(mjModel_* model, const Eigen::Vector3d& hold) const;
  void release(mjModel_* model) const;
  bool taken(const mjModel_* model) const;

  // The force the hold exerts on the hand, world coordinates, newtons, as the last
  // mj_forward or mj_step solved it; zero when the constraint is off.
  Eigen::Vector3d force(const mjModel_* model, const mjData_* data) const;

 private:
  int id_;
};

}  // namespace crux
