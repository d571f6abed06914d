#include "common/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/input_error.hpp"

namespace crux {

std::string read_input_file(const std::string& path, std::string_view kind) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw InputError(path, "is a directory, not a " + std::string(kind));
  if (!std::filesystem::exists(path, error)) throw InputError(path, "no such file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, std::string("cannot read the file: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace crux
