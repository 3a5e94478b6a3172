#include "flexure/io/toml_support.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "flexure/solver/common/status.h"

namespace flexure::io {

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

std::optional<double> toml_number(const toml::node& node) {
  if (const auto* i = node.as_integer()) return static_cast<double>(**i);
  if (const auto* f = node.as_floating_point()) return **f;
  return std::nullopt;
}

void toml_fail(const std::string& source, int line, const std::string& what) {
  throw InvalidInput(fmt::format("{}:{}: {}", source, line, what));
}

void check_toml_keys(const toml::table& table,
                     const std::set<std::string>& allowed,
                     const std::string& where,
                     const std::string& source) {
  for (const auto& [key, value] : table) {
    if (allowed.count(std::string(key.str())) == 0) {
      std::string list;
      for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
      toml_fail(source,
                line_of(value),
                fmt::format("unknown key '{}' in {} (allowed: {})", key.str(), where, list));
    }
  }
}

namespace {

// The nesting pre-scan. It follows just enough of the TOML grammar to know where keys are (a dot
// in a key adds a level, a dot in a value such as 1.5 does not) and skips strings and comments
// (brackets inside them are text). The depth is that of the tree toml++ builds: [a.b] followed by
// c.d = [[1]] is 2 (a.b) + 2 (c.d, the outer array) + 1 (the inner array) = 5; an array of tables
// [[a]] counts 2 (the array, its table).
class NestingScan {
 public:
  NestingScan(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  void run() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
        if (frames_.empty()) start_statement();
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\r') {
        ++pos_;
        continue;
      }
      if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        continue;
      }
      const bool first_on_line = line_start_;
      line_start_ = false;
      if (c == '"' || c == '\'') {
        key_token();
        skip_string();
        continue;
      }
      ++pos_;
      switch (c) {
        case '[':
          if (frames_.empty() && first_on_line) {
            header();
          } else {
            push(false);
          }
          break;
        case '{':
          push(true);
          break;
        case ']':
        case '}':
          if (!frames_.empty()) frames_.pop_back();
          in_key_ = false;  // the rest of the enclosing value, up to ',' or the end of the line
          break;
        case '.':
          if (in_key_) {
            ++key_parts_;
            check(base() + key_parts_);
          }
          break;
        case '=':
          in_key_ = false;
          value_depth_ = base() + key_parts_;
          break;
        case ',':
          if (!frames_.empty() && frames_.back().inline_table) {
            in_key_ = true;
            key_parts_ = 0;
          }
          break;
        default:
          key_token();
          break;
      }
    }
  }

 private:
  struct Frame {
    int depth = 0;  // depth of the array or inline table itself (a top-level key's value: 1)
    bool inline_table = false;
  };

  void start_statement() {
    line_start_ = true;
    in_key_ = true;
    key_parts_ = 0;
  }

  // The first character of a key part: a key has at least one part.
  void key_token() {
    if (in_key_ && key_parts_ == 0) {
      key_parts_ = 1;
      check(base() + 1);
    }
  }

  // Depth of the table (or array) that holds the key or value being read.
  int base() const {
    if (frames_.empty()) return table_depth_;
    return frames_.back().depth;
  }

  // An array or inline table opened in the current value: it sits where its key puts it (a.b = []
  // is two levels down) or, as an array element, one level below the array.
  void push(bool inline_table) {
    const int depth = frames_.empty()               ? value_depth_
                      : frames_.back().inline_table ? frames_.back().depth + key_parts_
                                                    : frames_.back().depth + 1;
    frames_.push_back(Frame{depth, inline_table});
    check(depth);
    in_key_ = inline_table;
    key_parts_ = 0;
  }

  // [a.b.c] or [[a.b.c]]: the table every following key/value line belongs to.
  void header() {
    int depth = 1;
    if (pos_ < text_.size() && text_[pos_] == '[') {
      ++pos_;
      ++depth;  // an array of tables is one more level
    }
    while (pos_ < text_.size() && text_[pos_] != ']' && text_[pos_] != '\n') {
      const char c = text_[pos_];
      if (c == '"' || c == '\'') {
        skip_string();
        continue;
      }
      if (c == '.') check(++depth);
      ++pos_;
    }
    while (pos_ < text_.size() && text_[pos_] == ']') ++pos_;
    check(depth);
    table_depth_ = depth;
    in_key_ = false;  // only a comment may follow on this line
  }

  // A basic ("...", with escapes), literal ('...') or multi-line (""" or ''') string, counting the
  // lines it spans. An unterminated string ends the scan at the end of its line (single-line) or of
  // the text; toml++ then reports it.
  void skip_string() {
    const char quote = text_[pos_];
    const bool multi_line = text_.compare(pos_, 3, std::string(3, quote)) == 0;
    pos_ += multi_line ? 3 : 1;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\\' && quote == '"') {
        if (pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') {
          if (!multi_line) return;  // a syntax error toml++ reports; the string ends here
          ++line_;
        }
        pos_ += 2;
        continue;
      }
      if (c == '\n') {
        if (!multi_line) return;
        ++line_;
      }
      if (c == quote) {
        if (!multi_line) {
          ++pos_;
          return;
        }
        if (text_.compare(pos_, 3, std::string(3, quote)) == 0) {
          pos_ += 3;
          // Up to two more quotes may close the string ("""a"""" is a" followed by the close).
          while (pos_ < text_.size() && text_[pos_] == quote) ++pos_;
          return;
        }
      }
      ++pos_;
    }
  }

  void check(int depth) const {
    if (depth > kMaxTomlNesting) {
      toml_fail(source_,
                line_,
                fmt::format("tables, keys and arrays are nested more than {} levels deep (the "
                            "limit; flexure's files need at most 3)",
                            kMaxTomlNesting));
    }
  }

  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  int line_ = 1;
  bool line_start_ = true;
  bool in_key_ = true;         // reading a key (before '='), not a value
  int key_parts_ = 0;          // parts of the key being read (a.b.c: 3)
  int table_depth_ = 0;        // depth of the current [table] header
  int value_depth_ = 0;        // depth of the top-level key being assigned
  std::vector<Frame> frames_;  // open arrays and inline tables
};

}  // namespace

void check_toml_limits(std::string_view text, const std::string& source) {
  if (text.size() > kMaxTomlBytes) {
    // The line where the limit is crossed, so that the message points into the file.
    const std::string_view head = text.substr(0, kMaxTomlBytes);
    const int line = 1 + static_cast<int>(std::count(head.begin(), head.end(), '\n'));
    toml_fail(source,
              line,
              fmt::format("the file is longer than the limit of {} bytes (1 MiB) for a TOML input "
                          "(flexure's chain and mechanism files are a few kB)",
                          kMaxTomlBytes));
  }
  NestingScan(text, source).run();
}

std::string read_toml_file(const std::string& path, const std::string& what) {
  // A directory opens as an empty stream on Linux and would be reported as a file without its
  // required keys; say what is wrong instead.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InvalidInput(fmt::format("cannot read {} '{}': it is a directory", what, path));
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InvalidInput(fmt::format("cannot read {} '{}': {}",
                                   what,
                                   path,
                                   errno != 0 ? std::strerror(errno) : "cannot open it"));
  }
  std::string text(kMaxTomlBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw InvalidInput(fmt::format("cannot read {} '{}': read error", what, path));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

}  // namespace flexure::io
