#pragma once
// Building the immutable BodyModel from a URDF file (urdfdom): the joint tree, limits,
// masses and the four grasp frames, with every problem of the file reported as one
// InputError naming it.

#include <string>

#include "body/body_model.hpp"

namespace crux {

// Loads and validates a URDF. Throws InputError("<path>", "<problem>") on any problem:
// unreadable file or XML, a root that is not 3 prismatic joints along x, y, z, a joint
// count other than 32 revolute, a joint without limits, an unsupported joint type, or a
// missing grasp frame.
BodyModel load_body_model(const std::string& urdf_path, const GraspFrameNames& frames = {});
BodyModel load_body_model_from_string(const std::string& urdf_xml, const std::string& source,
                                      const GraspFrameNames& frames = {});

// The repository's 1.70 m human (models/crux_human.urdf): $CRUX_MODEL_DIR/crux_human.urdf
// when that variable is set, else the first share/crux/models/ found going up from the
// folder of the file that holds this code: the crux binary (<prefix>/bin) or the Python
// module (<prefix>/lib/python3.X/dist-packages/crux), in an install or the build tree.
std::string default_body_model_path();

}  // namespace crux
