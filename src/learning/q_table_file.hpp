#pragma once
// Q-tables on disk (Q_grid is what transfer carries between walls): a versioned binary
// format, little-endian whatever the machine.
//
//   magic      8 bytes  "CRUXQTAB"
//   version    u32      2
//   actions    u32      action count A
//   space      u32      byte count S, then S bytes of UTF-8: the state space the codes
//                       belong to, so a table is never read with another space's codes
//   rows       u64      row count R
//   R times:   state u64, A x value f64, A x visits u32
//   checksum   u64      FNV-1a 64 of every byte before it
//
// Rows are in increasing state order, so the same table gives the same bytes.

#include <cstddef>
#include <cstdint>
#include <string>

#include "learning/q_table.hpp"

namespace crux {

inline constexpr std::uint32_t kQTableFileVersion = 2;
inline constexpr std::size_t kMaxStateSpaceNameBytes = 4096;

// The checksum field: FNV-1a 64 of the first `length` bytes.
std::uint64_t q_table_checksum(const std::string& bytes, std::size_t length);

// Written to a temporary name and renamed into place. `state_space` names the space of
// the state and action codes (for example the moving grid's shape).
void save_q_table(const std::string& path, const QTable& table, const std::string& state_space);

// Throws InputError(path, problem) for a missing, empty, foreign, wrong-version,
// truncated or corrupted file, or one whose action count or state space differs from
// those expected.
QTable load_q_table(const std::string& path, int expected_action_count, const std::string& expected_state_space);
// The same for a file's bytes already read; `source` names them in errors.
QTable parse_q_table(const std::string& bytes, const std::string& source, int expected_action_count,
                     const std::string& expected_state_space);

}  // namespace crux
