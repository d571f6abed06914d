#include "support/trained_run.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
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
  // Under ctest the fixture Fixture.TrainedRun trains it once for every test process that
  // needs it (each test case is a process of its own); run alone, a process trains its own.
  if (const char* shared = std::getenv("CRUX_TRAINED_RUN")) {
    static const std::filesystem::path folder = shared;
    return folder;
  }
  static const RemovedAtExit folder = [] {
    const std::filesystem::path path = temporary_path("trained_run_" + std::to_string(::getpid()));
    const Outcome outcome = run_crux("train --wall-seed 3 --seed 5 --overwrite -o " + path.string());
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    return RemovedAtExit{path};
  }();
  return folder.path;
}

RunFolder read_trained_run() {
  RunFolder folder = locate_run_folder(trained_run_folder());
  read_run_climb(folder, human_model());
  return folder;
}

std::filesystem::path edited_trained_run(const std::string& name, const std::string& file,
                                         const std::function<void(std::string&)>& edit) {
  const std::filesystem::path copy = temporary_path(name + "_" + std::to_string(::getpid()));
  std::filesystem::copy(trained_run_folder(), copy, std::filesystem::copy_options::recursive);
  std::string text;
  {
    std::ifstream in(copy / file, std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  edit(text);
  std::ofstream(copy / file, std::ios::binary | std::ios::trunc) << text;
  return copy;
}

}  // namespace crux::testing
