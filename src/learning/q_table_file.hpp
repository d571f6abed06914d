#pragma once
// Q-tables on disk (Q_grid is what transfer carries between walls): a versioned binary
// format, little-endian whatever the machine.
//
//   magic      8 bytes  "CRUXQTAB"
//   version    u32      1
//   actions    u32      action count A
//   rows       u64      row count R
//   R times:   state u64, A x value f64, A x visits u32
//   checksum   u64      FNV-1a 64 of every byte before it
//
// Rows are in increasing state order, so the same table gives the same bytes.

#include <string>

#include "learning/q_table.hpp"

namespace crux {

inline constexpr std::uint32_t kQTableFileVersion = 1;

// Written to a temporary name and renamed into place.
void save_q_table(const std::string& path, const QTable& table);

// Throws InputError(path, problem) for a missing, empty, foreign, wrong-version,
// truncated or corrupted file, or one whose action count differs from
// `expected_action_count`.
QTable load_q_table(const std::string& path, int expected_action_count);

}  // namespace crux
