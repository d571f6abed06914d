#include "simulation/mujoco_model.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include <mujoco/mujoco.h>

#include "common/input_error.hpp"

namespace crux {

namespace {

// MuJoCo's default handler appends warnings to MUJOCO_LOG.TXT in the working directory;
// crux reads the counts in mjData::warning instead, and writes no file of its own.
void ignore_warning(const char*) {}

}  // namespace

MujocoModel::MujocoModel(const std::string& mjcf, const std::string& source) {
  mju_user_warning = ignore_warning;
  // MuJoCo 2.2.2 reads text through a virtual file system (2 MB of names: on the heap).
  const auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  constexpr const char* kName = "model.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), kName, static_cast<int>(mjcf.size())) != 0) {
    throw InputError(source, "MuJoCo could not hold the model's text in memory");
  }
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), kName)], mjcf.data(), mjcf.size());
  std::array<char, 1000> error{};
  model_.reset(mj_loadXML(kName, vfs.get(), error.data(), static_cast<int>(error.size())));
  mj_deleteVFS(vfs.get());
  if (!model_) {
    std::string message = error.data();  // over several lines: one, as every crux error
    std::replace(message.begin(), message.end(), '\n', ' ');
    throw InputError(source, "MuJoCo refused the model: " + message);
  }
}

MujocoModel::MujocoModel(const MujocoModel& other) : model_(mj_copyModel(nullptr, other.model_.get())) {}

MujocoModel::~MujocoModel() = default;

void MujocoModel::Deleter::operator()(mjModel_* model) const { mj_deleteModel(model); }

}  // namespace crux
