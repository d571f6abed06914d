#pragma once
// The rows of the CSV files crux writes (iterations.csv, episodes.csv, climb.csv):
// cells separated by commas, never quoted, one header line. Every error is one line
// naming the file and the line.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace crux {

// The cells of one line: "a,,b" has three, "" one.
std::vector<std::string_view> split_csv_line(std::string_view line);

// The lines after the header, which must be `header`; a newline ends every line.
// InputError(file, ...) for an empty text, a text cut after its last newline, or another
// header. The views point into `text`.
std::vector<std::string_view> csv_rows(std::string_view text, const std::string& file, std::string_view header);

// Row `index` of csv_rows split into cells, which must be `columns`: InputError(file,
// "line N: ...") counting the header as line 1.
std::vector<std::string_view> csv_cells(std::string_view row, std::size_t index, std::size_t columns,
                                        const std::string& file);

// The line number of row `index` of csv_rows (the header is line 1).
constexpr std::size_t csv_line_number(std::size_t index) { return index + 2; }

// A whole cell as a number: InputError(file, "line N: 'cell' is not an integer / a
// number / finite").
int csv_integer(std::string_view cell, const std::string& file, std::size_t line);
double csv_number(std::string_view cell, const std::string& file, std::size_t line);

}  // namespace crux
