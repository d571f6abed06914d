// libFuzzer harness for Q-table files, read as a Q_grid of the paper's grid: a table or
// an InputError, nothing else. The seed is a real q_grid.bin (fuzz/corpus/q_table).
// Each input is read twice: as given, and with its checksum made right, since random
// bytes almost never match the checksum and would not reach the header's other checks
// and the rows.
#include <cstddef>
#include <cstdint>
#include <string>

#include "agent_space/moving_grid.hpp"
#include "common/input_error.hpp"
#include "learning/q_table_file.hpp"

namespace {

void read_as_q_grid(const std::string& bytes) {
  static const crux::GridParameters kGrid;
  static const std::string kSpace = crux::describe_grid(kGrid);
  try {
    crux::parse_q_table(bytes, "fuzz.bin", kGrid.tile_count(), kSpace);
  } catch (const crux::InputError&) {
  }
}

// The last 8 bytes replaced by the checksum of those before them, little-endian.
std::string with_checksum_made_right(std::string bytes) {
  if (bytes.size() < 8) return bytes;
  const std::uint64_t hash = crux::q_table_checksum(bytes, bytes.size() - 8);
  for (std::size_t i = 0; i < 8; ++i) bytes[bytes.size() - 8 + i] = static_cast<char>((hash >> (8 * i)) & 0xFF);
  return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  read_as_q_grid(bytes);
  read_as_q_grid(with_checksum_made_right(bytes));
  return 0;
}
