#pragma once
// A foot's footing in MuJoCo (docs/PHYSICS.md, "Performed in MuJoCo"): the plane a foot
// stands on, a mocap box that the simulation places where the foot takes its hold, its
// top face normal to the hold's support direction and just under the foot's contact
// sphere, so that the foot's frictional contact with it is the static model's point
// contact at the grasp point. The IK places a grasp point anywhere within the grasp radius
// of its hold, so a fixed hold shape would leave a foot in the air or inside it; the hand's
// grasp anchor is written where the hand arrives for the same reason.

#include <Eigen/Core>

#include "body/limb.hpp"

struct mjModel_;
struct mjData_;

namespace crux {

class Footing {
 public:
  // std::invalid_argument when the model has no mocap body mjcf_footing_name(foot).
  Footing(const mjModel_* model, Limb foot);

  // The footing under the contact sphere of a foot whose grasp point is `grasp_point`,
  // facing `support` (unit), both in world coordinates. Writes the data's mocap pose.
  void take(mjData_* data, const Eigen::Vector3d& grasp_point, const Eigen::Vector3d& support) const;
  // Parked out of reach (simulation/mjcf_model's kParkedFooting).
  void release(mjData_* data) const;
  bool taken(const mjData_* data) const;
  int body() const { return body_; }  // the footing's MuJoCo body

 private:
  int body_;
  int mocap_;
};

}  // namespace crux
