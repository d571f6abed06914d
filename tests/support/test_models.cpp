#include "support/test_models.hpp"
#include "body/urdf_loader.hpp"

#include <stdlib.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace crux::testing {

std::string linear_policy_json(int column, double weight, double max_span) {
  std::vector<double> row(66, 0.0);
  row.at(static_cast<std::size_t>(column)) = weight;
  return fmt::format(R"({{"format": "crux-policy", "version": 1, "observation": "reach", "max_candidates": 32, )"
                     R"("max_span": {}, "activation": "relu", "slot_layers": [{{"weight": [[{}]], "bias": [0]}}], )"
                     R"("value_layers": []}})",
                     max_span, fmt::join(row, ", "));
}

const BodyModel& human_model() {
  static const BodyModel model = load_body_model(default_body_model_path());
  return model;
}

std::string human_urdf_text() {
  std::ifstream in(default_body_model_path());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Posture random_posture(const BodyModel& model, Random& random, const Eigen::Vector3d& root) {
  Posture g;
  for (int i = 0; i < kRootDof; ++i) g[i] = root[i] + random.uniform(-0.5, 0.5);
  for (int i = kRootDof; i < kConfigurationDof; ++i)
    g[i] = random.uniform(model.lower_limits[i], model.upper_limits[i]);
  return g;
}

std::string root_translations_urdf() {
  std::string urdf = "<link name=\"world\"/><link name=\"rx\"/><link name=\"ry\"/>";
  const char* const axes[kRootDof] = {"1 0 0", "0 1 0", "0 0 1"};
  const char* const parents[kRootDof] = {"world", "rx", "ry"};
  const char* const children[kRootDof] = {"rx", "ry", "torso"};
  for (int i = 0; i < kRootDof; ++i) {
    urdf += fmt::format(
        "<joint name=\"root_{}\" type=\"prismatic\"><parent link=\"{}\"/><child link=\"{}\"/><axis xyz=\"{}\"/>"
        "<limit lower=\"-100\" upper=\"100\" effort=\"1\" velocity=\"1\"/></joint>",
        i, parents[i], children[i], axes[i]);
  }
  return urdf;
}

std::string synthetic_tree_urdf(std::uint64_t seed) {
  Random random(seed);
  std::ostringstream urdf;
  const auto inertial = [&](double mass) {
    return fmt::format(
        "<inertial><origin xyz=\"{} {} {}\" rpy=\"0 0 0\"/><mass value=\"{}\"/>"
        "<inertia ixx=\"0.01\" ixy=\"0\" ixz=\"0\" iyy=\"0.01\" iyz=\"0\" izz=\"0.01\"/></inertial>",
        random.uniform(-0.1, 0.1), random.uniform(-0.1, 0.1), random.uniform(-0.1, 0.1), mass);
  };
  urdf << "<robot name=\"synthetic\"><link name=\"world\"/>"
       << "<link name=\"rx\"/><link name=\"ry\"/><link name=\"torso\">" << inertial(20.0) << "</link>"
       << "<joint name=\"root_x\" type=\"prismatic\"><parent link=\"world\"/><child link=\"rx\"/>"
       << "<axis xyz=\"1 0 0\"/><limit lower=\"-100\" upper=\"100\" effort=\"1\" velocity=\"1\"/></joint>"
       << "<joint name=\"root_y\" type=\"prismatic\"><parent link=\"rx\"/><child link=\"ry\"/>"
       << "<axis xyz=\"0 1 0\"/><limit lower=\"-100\" upper=\"100\" effort=\"1\" velocity=\"1\"/></joint>"
       << "<joint name=\"root_z\" type=\"prismatic\"><parent link=\"ry\"/><child link=\"torso\"/>"
       << "<axis xyz=\"0 0 1\"/><limit lower=\"-100\" upper=\"100\" effort=\"1\" velocity=\"1\"/></joint>";
  const char* const frames[kLimbCount] = {"right_palm", "left_palm", "right_foot_ball", "left_foot_ball"};
  for (int limb = 0; limb < kLimbCount; ++limb) {
    std::string parent = "torso";
    for (int j = 0; j < 8; ++j) {
      const std::string link = fmt::format("limb{}_link{}", limb, j);
      urdf << fmt::format("<link name=\"{}\">{}</link>", link, inertial(random.uniform(0.5, 3.0)));
      urdf << fmt::format(
          "<joint name=\"limb{}_joint{}\" type=\"revolute\"><parent link=\"{}\"/><child link=\"{}\"/>"
          "<origin xyz=\"{} {} {}\" rpy=\"{} {} {}\"/><axis xyz=\"{} {} {}\"/>"
          "<limit lower=\"{}\" upper=\"{}\" effort=\"1\" velocity=\"1\"/></joint>",
          limb, j, parent, link, random.uniform(-0.2, 0.2), random.uniform(-0.2, 0.2), random.uniform(-0.3, 0.1),
          random.uniform(-3, 3), random.uniform(-1.5, 1.5), random.uniform(-3, 3), random.uniform(-1, 1),
          random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-2.5, -0.1), random.uniform(0.1, 2.5));
      parent = link;
    }
    urdf << fmt::format("<link name=\"{}\"/>", frames[limb])
         << fmt::format(
                "<joint name=\"{}_fixed\" type=\"fixed\"><parent link=\"{}\"/><child link=\"{}\"/>"
                "<origin xyz=\"{} {} {}\" rpy=\"{} 0 0\"/></joint>",
                frames[limb], parent, frames[limb], random.uniform(-0.1, 0.1), random.uniform(-0.1, 0.1),
                random.uniform(-0.2, 0.0), random.uniform(-1, 1));
  }
  urdf << "</robot>";
  return urdf.str();
}

std::string synthetic_tree_urdf_for_mujoco(std::uint64_t seed) {
  const std::string human = human_urdf_text();
  const auto begin = human.find("<mujoco>");
  const auto end = human.find("</mujoco>");
  if (begin == std::string::npos || end == std::string::npos) {
    throw std::runtime_error("test fixture: the human has no <mujoco> element");
  }
  const std::string element = human.substr(begin, end + std::string("</mujoco>").size() - begin);
  return replaced(synthetic_tree_urdf(seed), "<robot name=\"synthetic\">", "<robot name=\"synthetic\">" + element);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("test fixture: '" + from + "' not found");
  return text.replace(at, from.size(), to);
}

namespace {

// A fresh folder for one test process, removed when the process ends. Named after the
// pid, it outlived its process, and a later process given the same pid found an earlier
// one's outputs (a `crux train -o` into an existing run then failed).
struct ProcessFolder {
  std::filesystem::path path;
  ProcessFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "crux-tests-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a test folder: " + pattern);
    path = pattern;
  }
  ~ProcessFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

}  // namespace

const std::filesystem::path& test_folder() {
  static const ProcessFolder folder;
  return folder.path;
}

std::filesystem::path write_temporary(const std::string& name, const std::string& contents) {
  const auto& dir = test_folder();
  const auto path = dir / name;
  std::ofstream(path, std::ios::binary) << contents;
  return path;
}

std::filesystem::path temporary_path(const std::string& name) {
  const auto& dir = test_folder();
  std::filesystem::remove_all(dir / name);
  return dir / name;
}

}  // namespace crux::testing
