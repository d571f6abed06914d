#include "learning/q_table_file.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "common/atomic_file.hpp"
#include "common/counted.hpp"
#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "common/printable.hpp"

namespace crux {

namespace {

constexpr char kQTableMagic[8] = {'C', 'R', 'U', 'X', 'Q', 'T', 'A', 'B'};
constexpr std::size_t kFixedHeaderSize = 8 + 4 + 4 + 4 + 8;  // the space's bytes come on top

template <typename T>
void put(std::string& out, T value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof(T));
  for (std::size_t i = 0; i < sizeof(T); ++i) out.push_back(static_cast<char>((bits >> (8 * i)) & 0xFF));
}

template <typename T>
T get(const std::string& in, std::size_t& at) {
  std::uint64_t bits = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i)
    bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(in[at + i])) << (8 * i);
  at += sizeof(T);
  T value;
  std::memcpy(&value, &bits, sizeof(T));
  return value;
}

}  // namespace

std::uint64_t q_table_checksum(const std::string& bytes, std::size_t length) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < length; ++i) {
    hash ^= static_cast<unsigned char>(bytes[i]);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

void save_q_table(const std::string& path, const QTable& table, const std::string& state_space) {
  if (state_space.size() > kMaxStateSpaceNameBytes)
    throw std::invalid_argument("save_q_table: state space name too long");
  std::string out(kQTableMagic, sizeof(kQTableMagic));
  put<std::uint32_t>(out, kQTableFileVersion);
  put<std::uint32_t>(out, static_cast<std::uint32_t>(table.action_count()));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(state_space.size()));
  out += state_space;
  put<std::uint64_t>(out, table.state_count());
  table.for_each_row([&](StateCode state, std::span<const double> values, std::span<const std::uint32_t> visits) {
    put<std::uint64_t>(out, state);
    for (const double v : values) put<double>(out, v);
    for (const std::uint32_t v : visits) put<std::uint32_t>(out, v);
  });
  put<std::uint64_t>(out, q_table_checksum(out, out.size()));
  write_file_atomically(path, out);
}

QTable load_q_table(const std::string& path, int expected_action_count, const std::string& expected_state_space) {
  return parse_q_table(read_input_file(path, "Q-table file"), path, expected_action_count, expected_state_space);
}

QTable parse_q_table(const std::string& bytes, const std::string& path, int expected_action_count,
                     const std::string& expected_state_space) {
  if (bytes.empty()) throw InputError(path, "the file is empty");
  if (bytes.size() < sizeof(kQTableMagic) || std::memcmp(bytes.data(), kQTableMagic, sizeof(kQTableMagic)) != 0) {
    throw InputError(path, "not a crux Q-table file (no CRUXQTAB header)");
  }
  if (bytes.size() < sizeof(kQTableMagic) + 4) throw InputError(path, "truncated: the header is incomplete");
  std::size_t at = sizeof(kQTableMagic);
  const auto version = get<std::uint32_t>(bytes, at);
  if (version == 1) {
    throw InputError(path, fmt::format("Q-table file version 1 does not record the state space it was learnt on; "
                                       "this crux reads version {} (train again to write one)",
                                       kQTableFileVersion));
  }
  if (version != kQTableFileVersion) {
    throw InputError(path, fmt::format("unsupported Q-table file version {} (this crux reads version {})", version,
                                       kQTableFileVersion));
  }
  if (bytes.size() < kFixedHeaderSize) throw InputError(path, "truncated: the header is incomplete");
  const auto actions = get<std::uint32_t>(bytes, at);
  const auto space_size = get<std::uint32_t>(bytes, at);
  if (space_size > kMaxStateSpaceNameBytes || space_size > bytes.size() - kFixedHeaderSize) {
    throw InputError(path,
                     fmt::format("truncated or corrupted: a state space name of {}", counted(space_size, "byte")));
  }
  const std::string state_space = bytes.substr(at, space_size);
  at += space_size;
  const auto rows = get<std::uint64_t>(bytes, at);
  const std::size_t header_size = kFixedHeaderSize + space_size;
  const std::uint64_t row_size = 8 + 12 * static_cast<std::uint64_t>(actions);
  if (actions == 0 || rows > (bytes.size() - header_size) / row_size) {
    throw InputError(path, fmt::format("truncated or corrupted: {} of {} do not fit in {}", counted(rows, "row"),
                                       counted(actions, "action"), counted(bytes.size(), "byte")));
  }
  const std::uint64_t expected_size = header_size + rows * row_size + 8;
  if (bytes.size() != expected_size) {
    throw InputError(path, fmt::format("{}: expected {} for {}, found {}",
                                       bytes.size() < expected_size ? "truncated" : "trailing data",
                                       counted(expected_size, "byte"), counted(rows, "row"), bytes.size()));
  }
  std::size_t checksum_at = bytes.size() - 8;
  if (get<std::uint64_t>(bytes, checksum_at) != q_table_checksum(bytes, bytes.size() - 8)) {
    throw InputError(path, "corrupted: the checksum does not match the contents");
  }
  if (static_cast<int>(actions) != expected_action_count) {
    throw InputError(path, fmt::format("the table has {} where {} are expected (a different grid?)",
                                       counted(actions, "action"), expected_action_count));
  }
  if (state_space != expected_state_space) {
    throw InputError(path, fmt::format("the table was learnt on {}, this run uses {}", printable(state_space),
                                       printable(expected_state_space)));
  }
  QTable table(static_cast<int>(actions));
  for (std::uint64_t r = 0; r < rows; ++r) {
    const auto state = get<std::uint64_t>(bytes, at);
    for (std::uint32_t a = 0; a < actions; ++a) {
      const double value = get<double>(bytes, at);
      if (!std::isfinite(value))
        throw InputError(path, fmt::format("corrupted: a value of state {} is not finite", state));
      table.set_value(state, static_cast<ActionCode>(a), value);
    }
    for (std::uint32_t a = 0; a < actions; ++a)
      table.set_visits(state, static_cast<ActionCode>(a), get<std::uint32_t>(bytes, at));
  }
  return table;
}

}  // namespace crux
