#pragma once
// The data tables of data/*.csv: a comment block, a header row of column names, rows of values.
//
//   # Title
//   # Source: ...
//   # Columns: ... (units)
//   class,d,R,K1,K2,Xi,Phi
//   1A,16,0.8274,-,-,1.0030,0.4537
//
// Lines whose first non-blank character is '#' are comments (kept in comments()), blank lines are
// skipped, the first other line is the header and every later line one row. Fields are separated
// by commas and trimmed of blanks; there is no quoting, so a field cannot hold a comma. "-" is an
// empty cell (a value the source does not print, or a pivot without a spring).
//
// Cells are looked up by row and column name. Every failure (a missing column, a row with the
// wrong number of fields, a cell that is not a number) throws InvalidInput naming the table's
// source, the line and row, and the column.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flexure/solver/common/embedded_file.h"
#include "flexure/solver/common/status.h"

namespace flexure {

class CsvTable {
 public:
  // Parses `text`; `source` names the table in messages (the file's path).
  static CsvTable parse(std::string_view text, std::string source);
  static CsvTable parse(const EmbeddedFile& file);

  const std::string& source() const { return source_; }
  // The comment lines, without the '#' and one following blank.
  const std::vector<std::string>& comments() const { return comments_; }
  const std::vector<std::string>& column_names() const { return columns_; }
  std::size_t row_count() const { return rows_.size(); }
  bool has_column(std::string_view column) const;

  // The cell as written (trimmed). Rows count from 0.
  const std::string& text(std::size_t row, std::string_view column) const;
  // A finite number; "-", an empty cell or anything std::from_chars does not read whole throws.
  double number(std::size_t row, std::string_view column) const;
  // A finite number, or nullopt for "-".
  std::optional<double> optional_number(std::size_t row, std::string_view column) const;
  // A finite number, or `none` for "-".
  double number_or(std::size_t row, std::string_view column, double none) const;
  int integer(std::size_t row, std::string_view column) const;
  // "yes" or "no".
  bool yes_no(std::size_t row, std::string_view column) const;

  // An InvalidInput for a cell that reads but is not valid for its table (e.g. a name that does
  // not match its configuration), in the same form as the reader's own messages.
  InvalidInput cell_error(std::size_t row, std::string_view column, const std::string& what) const;

 private:
  std::size_t column_index(std::string_view column) const;
  const std::string& cell(std::size_t row, std::string_view column) const;

  std::string source_;
  std::vector<std::string> comments_;
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<std::size_t> lines_;  // line number (from 1) of each row in the text
};

}  // namespace flexure
