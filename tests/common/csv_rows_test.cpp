#include "common/csv_rows.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "common/input_error.hpp"

namespace crux {
namespace {

// The problem of the InputError that `read` raises, naming the file "f.csv".
std::string csv_problem(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "f.csv");
    return e.problem();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

TEST(CsvRows, SplitsALineAtEveryComma) {
  EXPECT_EQ(split_csv_line("a,,b"), (std::vector<std::string_view>{"a", "", "b"}));
  EXPECT_EQ(split_csv_line(""), (std::vector<std::string_view>{""}));
  EXPECT_EQ(split_csv_line("x,"), (std::vector<std::string_view>{"x", ""}));
}

TEST(CsvRows, GivesTheRowsAfterTheHeader) {
  EXPECT_EQ(csv_rows("a,b\n1,2\n3,4\n", "f.csv", "a,b"), (std::vector<std::string_view>{"1,2", "3,4"}));
  EXPECT_TRUE(csv_rows("a,b\n", "f.csv", "a,b").empty());
  EXPECT_EQ(csv_rows("a,b\n1,2\n\n", "f.csv", "a,b"), (std::vector<std::string_view>{"1,2", ""}))
      << "a blank line is a row, which its reader then refuses";
  EXPECT_EQ(csv_line_number(0), 2u);
}

TEST(CsvRows, RefusesAnEmptyTextAndAnotherHeader) {
  EXPECT_EQ(csv_problem([] { csv_rows("", "f.csv", "a,b"); }), "is empty; the header line must be 'a,b'");
  EXPECT_EQ(csv_problem([] { csv_rows("a,c\n1,2\n", "f.csv", "a,b"); }), "line 1: the header must be 'a,b', not 'a,c'");
  EXPECT_EQ(csv_problem([] { csv_rows("a\x1b,b\n", "f.csv", "a,b"); }),
            "line 1: the header must be 'a,b', not 'a\\x1b,b'")
      << "what is quoted stays printable";
  EXPECT_EQ(csv_problem([] { csv_rows(std::string(50, 'x') + "\n", "f.csv", "a,b"); }),
            "line 1: the header must be 'a,b', not '" + std::string(37, 'x') + "...'");
}

TEST(CsvRows, RefusesATextCutAfterItsLastNewline) {
  EXPECT_EQ(csv_problem([] { csv_rows("a,b\n1,2\n3,4", "f.csv", "a,b"); }),
            "does not end with a newline: it was cut short")
      << "'3,4' may be the start of '3,45'";
  EXPECT_EQ(csv_problem([] { csv_rows("a,b", "f.csv", "a,b"); }), "does not end with a newline: it was cut short");
}

TEST(CsvRows, ARowMustHaveItsColumns) {
  EXPECT_EQ(csv_cells("1,2,3", 0, 3, "f.csv"), (std::vector<std::string_view>{"1", "2", "3"}));
  EXPECT_EQ(csv_problem([] { csv_cells("1,2", 4, 3, "f.csv"); }), "line 6: 2 fields, not 3");
}

TEST(CsvRows, CellsAreWholeNumbers) {
  EXPECT_EQ(csv_integer("-12", "f.csv", 2), -12);
  EXPECT_DOUBLE_EQ(csv_number("0.25", "f.csv", 2), 0.25);
  EXPECT_DOUBLE_EQ(csv_number("-3", "f.csv", 2), -3.0);
  EXPECT_EQ(csv_problem([] { csv_integer("2.5", "f.csv", 3); }), "line 3: '2.5' is not an integer");
  EXPECT_EQ(csv_problem([] { csv_integer("", "f.csv", 3); }), "line 3: '' is not an integer");
  EXPECT_EQ(csv_problem([] { csv_integer("99999999999", "f.csv", 3); }), "line 3: '99999999999' is not an integer");
  EXPECT_EQ(csv_problem([] { csv_number("1.5x", "f.csv", 4); }), "line 4: '1.5x' is not a number");
  EXPECT_EQ(csv_problem([] { csv_number(" 1", "f.csv", 4); }), "line 4: ' 1' is not a number");
  EXPECT_EQ(csv_problem([] { csv_number("inf", "f.csv", 5); }), "line 5: 'inf' is not finite");
  EXPECT_EQ(csv_problem([] { csv_number("nan", "f.csv", 5); }), "line 5: 'nan' is not finite");
}

}  // namespace
}  // namespace crux
