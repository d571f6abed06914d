#pragma once
// Shared fixtures: the repository's human, random in-limit postures, a synthetic
// 32-joint tree with arbitrary axes and origins, and URDF text edits for bad models.

#include <cstdint>
#include <filesystem>
#include <string>

#include "body/body_model.hpp"
#include "common/random.hpp"

namespace crux::testing {

const BodyModel& human_model();
std::string human_urdf_text();

// Uniform in every joint's range; the root uniform in a 1 m cube around `root`.
Posture random_posture(const BodyModel& model, Random& random, const Eigen::Vector3d& root = {0.3, 0.6, 1.0});

// A body with the same root and grasp-frame contract as the human but 4 limbs of 8
// revolute joints with random axes, origin rotations (rpy) and offsets, and masses.
std::string synthetic_tree_urdf(std::uint64_t seed);

// The start of a small inline URDF with crux's root: the links world, rx and ry and the
// three prismatic root joints from the world to a link `torso`, which the caller declares.
std::string root_translations_urdf();

// The same with the human's own <mujoco> element, which MuJoCo needs to compile the
// massless links and keep the fixed frames (models/crux_human.urdf says why).
std::string synthetic_tree_urdf_for_mujoco(std::uint64_t seed);

// Replaces the first occurrence of `from` (which must exist) by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to);

// A policy file's text (climbing/policy_network) of one linear layer: each candidate's
// score is `weight` times input `column` of the 66 the network reads (57: the candidate's
// height over the free limb's grasp point, over the span), trained under max_span.
std::string linear_policy_json(int column, double weight, double max_span = 2.8);

// This test process's own folder under the temporary directory (TMPDIR), a fresh
// crux-tests-XXXXXX made on first use and removed when the process ends: ctest runs test
// cases in parallel processes, and no test writes to a path another process or the
// machine uses.
const std::filesystem::path& test_folder();

// A fresh file in test_folder() holding `contents`.
std::filesystem::path write_temporary(const std::string& name, const std::string& contents);

// A path in test_folder() where nothing exists yet.
std::filesystem::path temporary_path(const std::string& name);

}  // namespace crux::testing
