#pragma once
// A file a test wrote, read whole ("" when it is missing), for the tests that compare an
// output's bytes.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace crux::testing {

inline std::string read_output_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace crux::testing
