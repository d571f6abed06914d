#pragma once
// Bad user input (model, wall, config or table files; command-line values).
// The CLI turns it into one line "crux: <file>: <problem>" and exit code 2.

#include <stdexcept>
#include <string>

namespace crux {

class InputError : public std::runtime_error {
 public:
  InputError(std::string source, const std::string& problem)
      : std::runtime_error(source.empty() ? problem : source + ": " + problem),
        source_(std::move(source)) {}

  const std::string& source() const noexcept { return source_; }

 private:
  std::string source_;
};

}  // namespace crux
