// libFuzzer harness for Q-table files, read as a Q_grid of the paper's grid: a table or
// an InputError, nothing else. The seed is a real q_grid.bin (fuzz/corpus/q_table).
#include <cstddef>
#include <cstdint>
#include <string>

#include "agent_space/moving_grid.hpp"
#include "common/input_error.hpp"
#include "learning/q_table_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const crux::GridParameters kGrid;
  static const std::string kSpace = crux::describe_grid(kGrid);
  try {
    crux::parse_q_table(std::string(reinterpret_cast<const char*>(data), size), "fuzz.bin", kGrid.tile_count(), kSpace);
  } catch (const crux::InputError&) {
  }
  return 0;
}
