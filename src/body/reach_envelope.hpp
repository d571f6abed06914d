#pragma once
// The model's ReachEnvelope (body_model.hpp), computed once when the model is loaded.

#include "body/body_model.hpp"

namespace crux {

// For a model whose joints and grasp points are set.
ReachEnvelope compute_reach_envelope(const BodyModel& model);

}  // namespace crux
