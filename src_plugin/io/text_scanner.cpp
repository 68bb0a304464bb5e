#include "text_scanner.h"

#include "mesh_formats.h"

#include <charconv>
#include <sstream>
#include <system_error>
#include <type_traits>

namespace tri::mesh_io {

bool LineScanner::next(std::string_view &line) {
  if (pos_ >= text_.size())
    return false;
  std::size_t end = text_.find('\n', pos_);
  const std::size_t after = end == std::string_view::npos ? text_.size() : end + 1;
  if (end == std::string_view::npos)
    end = text_.size();
  if (end > pos_ && text_[end - 1] == '\r')
    --end;
  line = text_.substr(pos_, end - pos_);
  pos_ = after;
  ++number_;
  return true;
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

bool WordScanner::next(std::string_view &word) {
  std::size_t begin = 0;
  while (begin < rest_.size() && is_blank(rest_[begin]))
    ++begin;
  std::size_t end = begin;
  while (end < rest_.size() && !is_blank(rest_[end]))
    ++end;
  word = rest_.substr(begin, end - begin);
  rest_.remove_prefix(end);
  return !word.empty();
}

bool WordScanner::at_end() {
  while (!rest_.empty() && is_blank(rest_.front()))
    rest_.remove_prefix(1);
  return rest_.empty();
}

namespace {

// std::from_chars takes a '-' but not a '+'; a '+' is allowed here, once and before a digit or
// point, so "+-1" and "++1" stay malformed.
bool strip_plus(std::string_view &word) {
  if (word.size() < 2 || word.front() != '+')
    return true;
  word.remove_prefix(1);
  return word.front() != '+' && word.front() != '-';
}

template <typename T> NumberParse parse_whole_word(std::string_view word, T &value) {
  if (word.empty() || !strip_plus(word))
    return NumberParse::not_a_number;
  const char *end = word.data() + word.size();
  std::from_chars_result result{};
  if constexpr (std::is_floating_point_v<T>)
    result = std::from_chars(word.data(), end, value, std::chars_format::general);
  else
    result = std::from_chars(word.data(), end, value, 10);
  if (result.ec == std::errc::result_out_of_range && result.ptr == end)
    return NumberParse::out_of_range;
  if (result.ec != std::errc() || result.ptr != end)
    return NumberParse::not_a_number;
  return NumberParse::ok;
}

} // namespace

NumberParse parse_double(std::string_view word, double &value) {
  return parse_whole_word(word, value);
}

NumberParse parse_integer(std::string_view word, long long &value) {
  return parse_whole_word(word, value);
}

std::string number_complaint(std::string_view word, NumberParse outcome, const char *kind) {
  if (outcome == NumberParse::out_of_range)
    return quoted(word) + " is out of the range of " +
           (std::string(kind) == "an integer" ? "a 64-bit integer" : "a double");
  return quoted(word) + " where " + kind + " was expected";
}

void require_text(std::string_view bytes, const std::string &what) {
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if ((c < 0x20 || c > 0x7e) && c != '\n' && c != '\r' && c != '\t') {
      std::ostringstream os;
      os << what << ": byte 0x" << std::hex << int(c) << std::dec << " at offset " << i;
      throw FormatError(os.str());
    }
  }
}

std::string lowercase(std::string_view word) {
  std::string lower(word);
  for (char &c : lower)
    if (c >= 'A' && c <= 'Z')
      c = static_cast<char>(c - 'A' + 'a');
  return lower;
}

std::string quoted(std::string_view text) {
  // Cut, and bytes that are not printable written as \xNN: an OBJ may hold any byte, and a NUL
  // would end the message where LIGGGHTS prints it as a C string.
  constexpr std::size_t kLongest = 60;
  std::ostringstream os;
  os << '"';
  for (std::size_t i = 0; i < text.size() && i < kLongest; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c <= 0x7e)
      os << text[i];
    else
      os << "\\x" << std::hex << (c >> 4) << (c & 15) << std::dec;
  }
  os << (text.size() > kLongest ? "...\"" : "\"");
  return os.str();
}

} // namespace tri::mesh_io
