#pragma once
// A real run folder for the tests that read one back: crux train on random wall 3 with
// learning seed 5 and its 8000 iterations, which completes episodes and learns a greedy
// climb. Trained once per test process (ctest runs test cases in parallel processes).

#include <filesystem>

namespace crux::testing {

const std::filesystem::path& trained_run_folder();

}  // namespace crux::testing
