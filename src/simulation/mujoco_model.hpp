#pragma once
// A MuJoCo model compiled from MJCF text, owned (MuJoCo 2.2.2, Debian's libmujoco-dev):
// the immutable Model of a simulation, apart from the mjData each thread steps. A thread
// that writes model fields, as a grasp writes its constraint's anchor, works on a copy of
// its own.

#include <memory>
#include <string>

struct mjModel_;

namespace crux {

class MujocoModel {
 public:
  // Compiles `mjcf` as MuJoCo would the file `source`; an InputError naming `source` with
  // MuJoCo's own message when MuJoCo refuses it.
  MujocoModel(const std::string& mjcf, const std::string& source);
  MujocoModel(const MujocoModel& other);  // a deep copy (mj_copyModel)
  MujocoModel& operator=(const MujocoModel&) = delete;
  MujocoModel(MujocoModel&&) noexcept = default;
  MujocoModel& operator=(MujocoModel&&) noexcept = default;
  ~MujocoModel();

  const mjModel_* get() const { return model_.get(); }
  mjModel_* get() { return model_.get(); }

 private:
  struct Deleter {
    void operator()(mjModel_* model) const;
  };
  std::unique_ptr<mjModel_, Deleter> model_;
};

}  // namespace crux
