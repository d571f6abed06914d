#include "support/trained_run.hpp"

#include <unistd.h>

#include <string>
#include <system_error>

#include <gtest/gtest.h>

#include "support/run_crux.hpp"
#include "support/test_models.hpp"

namespace crux::testing {

namespace {

// Removes the process's run folder when the process ends.
struct RemovedAtExit {
  std::filesystem::path path;
  ~RemovedAtExit() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

}  // namespace

const std::filesystem::path& trained_run_folder() {
  static const RemovedAtExit folder = [] {
    const std::filesystem::path path = temporary_path("trained_run_" + std::to_string(::getpid()));
    const Outcome outcome = run_crux("train --wall-seed 3 --seed 5 --overwrite -o " + path.string());
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    return RemovedAtExit{path};
  }();
  return folder.path;
}

}  // namespace crux::testing
