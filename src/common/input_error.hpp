#pragma once
// Bad user input (model, wall, config or table files; command-line values).
// The CLI turns it into one line "crux: <file>: <problem>" and exit code 2.

#include <stdexcept>
#include <string>

namespace crux {

class InputError : public std::runtime_error {
 public:
  InputError(std::string source, std::string problem)
      : std::runtime_error(source.empty() ? problem : source + ": " + problem),
        source_(std::move(source)),
        problem_(std::move(problem)) {}

  const std::string& source() const noexcept { return source_; }
  const std::string& problem() const noexcept { return problem_; }

 private:
  std::string source_;
  std::string problem_;
};

}  // namespace crux
