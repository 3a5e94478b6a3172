#include "flexure/solver/common/csv_table.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <system_error>

namespace flexure {
namespace {

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  while (true) {
    const std::size_t comma = line.find(',');
    fields.emplace_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    line.remove_prefix(comma + 1);
  }
  return fields;
}

}  // namespace

CsvTable CsvTable::parse(const EmbeddedFile& file) {
  return parse(file.text, std::string(file.path));
}

CsvTable CsvTable::parse(std::string_view text, std::string source) {
  CsvTable table;
  table.source_ = std::move(source);
  std::size_t line_number = 0;
  bool have_header = false;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view raw = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    ++line_number;
    const std::string_view line = trim(raw);
    if (line.empty()) continue;
    if (line.front() == '#') {
      std::string_view comment = line.substr(1);
      if (!comment.empty() && comment.front() == ' ') comment.remove_prefix(1);
      table.comments_.emplace_back(comment);
      continue;
    }
    std::vector<std::string> fields = split_fields(line);
    if (!have_header) {
      for (std::size_t i = 0; i < fields.size(); ++i) {
        if (fields[i].empty()) {
          throw InvalidInput(fmt::format("{}, line {}: column {} of the header row has no name",
                                         table.source_,
                                         line_number,
                                         i + 1));
        }
        for (std::size_t j = 0; j < i; ++j) {
          if (fields[j] == fields[i]) {
            throw InvalidInput(fmt::format(
                "{}, line {}: column '{}' is named twice", table.source_, line_number, fields[i]));
          }
        }
      }
      table.columns_ = std::move(fields);
      have_header = true;
      continue;
    }
    if (fields.size() != table.columns_.size()) {
      throw InvalidInput(fmt::format("{}, line {} (row {}): {} fields, the header names {} columns",
                                     table.source_,
                                     line_number,
                                     table.rows_.size() + 1,
                                     fields.size(),
                                     table.columns_.size()));
    }
    table.rows_.push_back(std::move(fields));
    table.lines_.push_back(line_number);
  }
  if (!have_header) {
    throw InvalidInput(
        fmt::format("{}: no header row (only comments and blank lines)", table.source_));
  }
  return table;
}

bool CsvTable::has_column(std::string_view column) const {
  for (const std::string& name : columns_) {
    if (name == column) return true;
  }
  return false;
}

std::size_t CsvTable::column_index(std::string_view column) const {
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (columns_[i] == column) return i;
  }
  std::string names;
  for (const std::string& name : columns_) names += (names.empty() ? "" : ", ") + name;
  throw InvalidInput(
      fmt::format("{}: no column '{}' (the header names: {})", source_, column, names));
}

InvalidInput CsvTable::cell_error(std::size_t row,
                                  std::string_view column,
                                  const std::string& what) const {
  if (row >= rows_.size()) {
    return InvalidInput(fmt::format(
        "{}: row {}, column '{}': the table has {} rows", source_, row + 1, column, rows_.size()));
  }
  return InvalidInput(fmt::format(
      "{}, line {} (row {}), column '{}': {}", source_, lines_[row], row + 1, column, what));
}

const std::string& CsvTable::cell(std::size_t row, std::string_view column) const {
  const std::size_t index = column_index(column);
  if (row >= rows_.size()) throw cell_error(row, column, "");
  return rows_[row][index];
}

const std::string& CsvTable::text(std::size_t row, std::string_view column) const {
  return cell(row, column);
}

double CsvTable::number(std::size_t row, std::string_view column) const {
  const std::string& s = cell(row, column);
  double value = 0.0;
  const char* const end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, value);
  if (s.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw cell_error(row,
                     column,
                     s == "-" ? std::string("'-' (no value) where a number is required")
                              : fmt::format("'{}' is not a finite number", s));
  }
  return value;
}

std::optional<double> CsvTable::optional_number(std::size_t row, std::string_view column) const {
  if (cell(row, column) == "-") return std::nullopt;
  return number(row, column);
}

double CsvTable::number_or(std::size_t row, std::string_view column, double none) const {
  return optional_number(row, column).value_or(none);
}

int CsvTable::integer(std::size_t row, std::string_view column) const {
  const std::string& s = cell(row, column);
  int value = 0;
  const char* const end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, value);
  if (s.empty() || ec != std::errc() || ptr != end) {
    throw cell_error(row, column, fmt::format("'{}' is not an integer", s));
  }
  return value;
}

bool CsvTable::yes_no(std::size_t row, std::string_view column) const {
  const std::string& s = cell(row, column);
  if (s == "yes") return true;
  if (s == "no") return false;
  throw cell_error(row, column, fmt::format("'{}' is neither yes nor no", s));
}

}  // namespace flexure
