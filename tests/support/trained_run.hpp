#pragma once
// A real run folder for the tests that read one back: crux train on random wall 3 with
// learning seed 5 and its 8000 iterations, which completes episodes and learns a greedy
// climb. Trained once by ctest's fixture Fixture.TrainedRun (CRUX_TRAINED_RUN names its
// folder), or once per test process when a test binary runs alone.

#include <filesystem>
#include <functional>
#include <string>

#include "outputs/run_folder.hpp"

namespace crux::testing {

const std::filesystem::path& trained_run_folder();

// The trained run folder read back, its climb read with the human body.
RunFolder read_trained_run();

// A copy of the trained run folder (named `name`, per process) in which `edit` has
// changed the text of one file.
std::filesystem::path edited_trained_run(const std::string& name, const std::string& file,
                                         const std::function<void(std::string&)>& edit);

}  // namespace crux::testing
