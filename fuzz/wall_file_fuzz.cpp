// libFuzzer harness for the wall reader: any bytes either load as a wall or are refused
// with an InputError; anything else (a crash, a sanitizer report, another exception)
// is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/input_error.hpp"
#include "wall/wall_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const crux::Wall wall = crux::parse_wall(text, "fuzz.json");
    // A wall that loads must save and load back to the same holds.
    const crux::Wall again = crux::parse_wall(crux::wall_to_json(wall), "fuzz-again.json");
    if (again.holds.size() != wall.holds.size()) __builtin_trap();
  } catch (const crux::InputError&) {
  }
  return 0;
}
