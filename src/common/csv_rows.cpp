#include "common/csv_rows.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "common/counted.hpp"
#include "common/input_error.hpp"
#include "common/printable.hpp"

namespace crux {
namespace {

// A cell or a line echoed in an error stays short and on one line.
std::string quoted_cell(std::string_view text) {
  constexpr std::size_t kMaxQuoted = 40;
  return printable(text.size() <= kMaxQuoted ? text : text.substr(0, kMaxQuoted - 3)) +
         (text.size() <= kMaxQuoted ? "" : "...");
}

template <typename T>
T csv_value(std::string_view cell, const std::string& file, std::size_t line, const char* kind) {
  T value{};
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (cell.empty() || error != std::errc() || end != cell.data() + cell.size()) {
    throw InputError(file, fmt::format("line {}: '{}' is not {}", line, quoted_cell(cell), kind));
  }
  return value;
}

}  // namespace

std::vector<std::string_view> split_csv_line(std::string_view line) {
  std::vector<std::string_view> cells;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return cells;
    start = comma + 1;
  }
}

std::vector<std::string_view> csv_rows(std::string_view text, const std::string& file, std::string_view header) {
  if (text.empty()) throw InputError(file, fmt::format("is empty; the header line must be '{}'", header));
  // crux ends every line it writes; a file cut mid-row could still parse, with a wrong last value.
  if (text.back() != '\n') throw InputError(file, "does not end with a newline: it was cut short");
  std::vector<std::string_view> lines;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  if (lines.front() != header) {
    throw InputError(file,
                     fmt::format("line 1: the header must be '{}', not '{}'", header, quoted_cell(lines.front())));
  }
  lines.erase(lines.begin());
  return lines;
}

std::vector<std::string_view> csv_cells(std::string_view row, std::size_t index, std::size_t columns,
                                        const std::string& file) {
  std::vector<std::string_view> cells = split_csv_line(row);
  if (cells.size() != columns) {
    throw InputError(
        file, fmt::format("line {}: {}, not {}", csv_line_number(index), counted(cells.size(), "field"), columns));
  }
  return cells;
}

int csv_integer(std::string_view cell, const std::string& file, std::size_t line) {
  return csv_value<int>(cell, file, line, "an integer");
}

double csv_number(std::string_view cell, const std::string& file, std::size_t line) {
  const double value = csv_value<double>(cell, file, line, "a number");
  if (!std::isfinite(value)) {
    throw InputError(file, fmt::format("line {}: '{}' is not finite", line, quoted_cell(cell)));
  }
  return value;
}

}  // namespace crux
