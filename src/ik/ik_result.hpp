#pragma once

#include <vector>

#include "body/body_model.hpp"

namespace crux {

struct IkResult {
  bool reached = false;
  int iterations = 0;           // gradient (or linearisation) steps taken
  double simulated_time_s = 0;  // iterations x the simulated time step
  double residual_m = 0;        // largest grasp-point-to-hold distance at the last iterate
  Posture posture;              // the reached posture, or G_init when not reached (Algorithm 1)
};

// Postures sampled along a solve, for animation: the start, every `every`-th iterate,
// and the last iterate. Recording is off when `every` is 0 or `path` is null.
struct PathRecorder {
  std::vector<Posture>* path = nullptr;
  int every = 0;
  bool active() const { return path != nullptr && every > 0; }
  void start(const Posture& g) const {
    if (active()) path->assign(1, g);
  }
  void sample(int iteration, const Posture& g) const {
    if (active() && iteration % every == 0) path->push_back(g);
  }
  void finish(int iteration, const Posture& g) const {
    if (active() && iteration % every != 0) path->push_back(g);
  }
};

}  // namespace crux
