// Lines, words and numbers of the text mesh formats (ASCII STL, OBJ, ASCII PLY), shared so that
// the three parsers agree on what a line, a blank and a number are.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace tri::mesh_io {

// The lines of a text, numbered from 1. A line ends at '\n', which is not part of it, and so is
// not a '\r' before it (CRLF files read as LF files); the last line need not end with '\n'.
class LineScanner {
public:
  explicit LineScanner(std::string_view text) : text_(text) {}
  // The next line; false when there is none.
  bool next(std::string_view &line);
  // The number of the line that next() returned last (0 before the first).
  long long number() const { return number_; }

private:
  std::string_view text_;
  std::size_t pos_ = 0;
  long long number_ = 0;
};

// Blanks separate words: space, tab, '\r', '\v', '\f'.
bool is_blank(char c);

// The words of one line.
class WordScanner {
public:
  explicit WordScanner(std::string_view line) : rest_(line) {}
  // The next word; false when none is left.
  bool next(std::string_view &word);
  // True when only blanks are left.
  bool at_end();

private:
  std::string_view rest_;
};

// Outcome of parsing one word as a number.
enum class NumberParse { ok, not_a_number, out_of_range };

// The whole word as a decimal floating-point number: an optional sign, digits with an optional
// point, an optional exponent ("-1.5e-3", "+2", ".5", "5."), or inf/infinity/nan in any case.
// The result is the double nearest to the decimal value, as strtod gives, but independent of the
// C locale. Out of range: beyond the largest double, or so small that it would round to zero.
NumberParse parse_double(std::string_view word, double &value);

// The whole word as a decimal integer with an optional sign.
NumberParse parse_integer(std::string_view word, long long &value);

// What parse_double or parse_integer refused, said for a message: "\"x\" where a number was
// expected" or "\"1e999\" is out of the range of a double" (kind: "a number", "an integer").
std::string number_complaint(std::string_view word, NumberParse outcome, const char *kind);

// Throws FormatError("<what>: byte 0x.. at offset N") at the first byte of `bytes` that is not
// printable ASCII, tab, '\r' or '\n'.
void require_text(std::string_view bytes, const std::string &what);

// `word` in lower case (ASCII letters only).
std::string lowercase(std::string_view word);

// `text` in double quotes for a message: at most its first 60 bytes, those that are not
// printable ASCII written as \xNN.
std::string quoted(std::string_view text);

} // namespace tri::mesh_io
