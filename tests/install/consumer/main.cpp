// Forward kinematics of the installed body model at the standing posture, root at the
// origin: prints the right palm's position.
#include <cstdio>

#include "body/kinematics.hpp"
#include "body/urdf_loader.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const crux::BodyModel model = crux::load_body_model(argv[1]);
  crux::BodyData data(model);
  crux::forward_kinematics(model, data, crux::standing_posture(Eigen::Vector3d::Zero()));
  const Eigen::Vector3d& palm = data.points[1];  // e0, then the right hand
  std::printf("right_palm %.4f %.4f %.4f\n", palm.x(), palm.y(), palm.z());
  return 0;
}
