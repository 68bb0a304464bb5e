// PLY, ascii, binary_little_endian and binary_big_endian (the contract is in mesh_reader.h).
//
// The header declares elements, in the order the body holds them, each with a count and
// properties: scalars ("property TYPE NAME") and lists ("property list COUNT_TYPE VALUE_TYPE
// NAME"), with the types char/int8, uchar/uint8, short/int16, ushort/uint16, int/int32,
// uint/uint32, float/float32, double/float64. Read: the vertex element's x, y and z (any type;
// other properties skipped) and the face element's vertex_indices (or vertex_index) list of
// 0-based indices (integer types); every other element and property is skipped by its declared
// size. In ascii, an element instance is one line (blank lines are skipped) and its values are
// whole words.
#include "mesh_formats.h"
#include "text_scanner.h"

#include <climits>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace tri::mesh_io {

namespace {

enum class Format { ascii, binary_little_endian, binary_big_endian };
enum class Scalar { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

bool scalar_named(std::string_view name, Scalar &type) {
  static const struct {
    const char *name, *alias;
    Scalar type;
  } kTypes[] = {{"char", "int8", Scalar::int8},        {"uchar", "uint8", Scalar::uint8},
                {"short", "int16", Scalar::int16},     {"ushort", "uint16", Scalar::uint16},
                {"int", "int32", Scalar::int32},       {"uint", "uint32", Scalar::uint32},
                {"float", "float32", Scalar::float32}, {"double", "float64", Scalar::float64}};
  for (const auto &t : kTypes)
    if (name == t.name || name == t.alias) {
      type = t.type;
      return true;
    }
  return false;
}

int size_of(Scalar type) {
  switch (type) {
  case Scalar::int8:
  case Scalar::uint8:
    return 1;
  case Scalar::int16:
  case Scalar::uint16:
    return 2;
  case Scalar::int32:
  case Scalar::uint32:
  case Scalar::float32:
    return 4;
  case Scalar::float64:
    return 8;
  }
  return 0;
}

bool is_integer(Scalar type) { return type != Scalar::float32 && type != Scalar::float64; }

struct Property {
  std::string name;
  bool is_list = false;
  Scalar count_type = Scalar::uint8; // lists only
  Scalar value_type = Scalar::float32;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::ascii;
  std::vector<Element> elements;
  std::size_t body = 0; // offset of the first byte after the end_header line
};

[[noreturn]] void malformed(const std::string &what) {
  throw FormatError("PLY file is malformed: " + what);
}

Header parse_header(std::string_view bytes) {
  if (bytes.substr(0, 3) != "ply")
    throw FormatError("not a PLY file: it does not start with \"ply\"");
  // The first line that starts with end_header (a comment may mention it).
  const std::size_t line_start = bytes.find("\nend_header");
  if (line_start == std::string_view::npos)
    malformed("no \"end_header\" line");
  const std::size_t end_header = line_start + 1;
  const std::size_t newline = bytes.find('\n', end_header);
  Header header;
  header.body = newline == std::string_view::npos ? bytes.size() : newline + 1;
  const std::size_t after_keyword = end_header + std::strlen("end_header");
  for (std::size_t i = after_keyword; i < header.body; ++i)
    if (!is_blank(bytes[i]) && bytes[i] != '\n')
      malformed("\"end_header\" is not a line of its own");

  std::string format;
  LineScanner lines(bytes.substr(0, end_header));
  std::string_view line, keyword, word;
  while (lines.next(line)) {
    WordScanner words(line);
    words.next(keyword);
    if (keyword == "format") {
      if (!format.empty())
        malformed("a second \"format\" line");
      words.next(word);
      format = word;
    } else if (keyword == "element") {
      // Exactly "element NAME COUNT", COUNT in digits.
      Element e;
      std::string_view name, count, extra;
      long long parsed = 0;
      if (!words.next(name) || !words.next(count) || words.next(extra) ||
          count.find_first_not_of("0123456789") != std::string_view::npos ||
          parse_integer(count, parsed) != NumberParse::ok)
        malformed("bad element line " + quoted(line));
      e.name = name;
      e.count = static_cast<std::uint64_t>(parsed);
      for (const Element &other : header.elements)
        if (other.name == e.name)
          malformed("element \"" + e.name + "\" is declared twice");
      header.elements.push_back(e);
    } else if (keyword == "property") {
      if (header.elements.empty())
        malformed("property before any element");
      Property p;
      std::string_view type, name, extra;
      words.next(type);
      if (type == "list") {
        p.is_list = true;
        std::string_view count_type;
        words.next(count_type);
        if (!scalar_named(count_type, p.count_type) || !is_integer(p.count_type))
          malformed("list count type " + quoted(count_type) + " is not an integer type");
        words.next(type);
      }
      if (!scalar_named(type, p.value_type))
        malformed("unknown property type " + quoted(type));
      if (!words.next(name) || words.next(extra))
        malformed("bad property line " + quoted(line));
      p.name = name;
      Element &e = header.elements.back();
      for (const Property &other : e.properties)
        if (other.name == p.name)
          malformed("element \"" + e.name + "\" has two properties \"" + p.name + "\"");
      e.properties.push_back(p);
    } else if (keyword != "ply" && keyword != "comment" && keyword != "obj_info") {
      malformed("unexpected header line " + quoted(line));
    }
  }
  if (format == "ascii")
    header.format = Format::ascii;
  else if (format == "binary_little_endian")
    header.format = Format::binary_little_endian;
  else if (format == "binary_big_endian")
    header.format = Format::binary_big_endian;
  else
    malformed("unknown format " + quoted(format));
  for (const Element &e : header.elements)
    if (e.properties.empty())
      malformed("element \"" + e.name + "\" has no properties");
  return header;
}

const Element *find_element(const Header &header, const std::string &name) {
  for (const Element &e : header.elements)
    if (e.name == name)
      return &e;
  return nullptr;
}

// The body, one element instance after another, in ascii or binary.
class BodyReader {
public:
  BodyReader(std::string_view bytes, const Header &header)
      : bytes_(bytes), format_(header.format), pos_(header.body), lines_(bytes.substr(pos_)) {
    for (std::size_t i = 0; i < header.body; ++i)
      header_lines_ += bytes[i] == '\n';
  }

  // Starts instance `index` of `element` (for messages, and in ascii its line).
  void begin(const Element &element, std::uint64_t index) {
    element_ = &element;
    index_ = index;
    if (format_ == Format::ascii) {
      // The next line that is not blank (an instance has at least one value).
      std::string_view line;
      do {
        if (!lines_.next(line))
          truncated();
        words_ = WordScanner(line);
      } while (words_.at_end());
    }
  }

  // One value of a scalar property, as a double (exact for every PLY type).
  double value(Scalar type) {
    if (format_ != Format::ascii)
      return decode(type, take(size_of(type)));
    if (is_integer(type))
      return static_cast<double>(integer(type));
    std::string_view word = next_word();
    double value = 0;
    const NumberParse outcome = parse_double(word, value);
    if (outcome != NumberParse::ok)
      ascii_malformed(number_complaint(word, outcome, "a number"));
    return value;
  }

  // One value of an integer type (a list count or index).
  long long integer(Scalar type) {
    if (format_ != Format::ascii)
      return static_cast<long long>(decode(type, take(size_of(type))));
    std::string_view word = next_word();
    long long value = 0;
    const NumberParse outcome = parse_integer(word, value);
    if (outcome != NumberParse::ok)
      ascii_malformed(number_complaint(word, outcome, "an integer"));
    return value;
  }

  // Passes over `n` values of `type`, checking that they are there (and in ascii, numbers).
  void skip(Scalar type, std::uint64_t n) {
    if (format_ == Format::ascii) {
      for (std::uint64_t k = 0; k < n; ++k)
        value(type);
      return;
    }
    // In bytes: a list count of 4e9 must not mean 4e9 steps.
    const std::uint64_t size = static_cast<std::uint64_t>(size_of(type));
    if (n > (bytes_.size() - pos_) / size)
      truncated();
    pos_ += n * size;
  }

  // Whether `n` values of `type` can still follow in this instance (so that a list count can be
  // trusted with an allocation).
  bool can_hold(Scalar type, std::uint64_t n) const {
    if (format_ == Format::ascii)
      return n <= bytes_.size(); // a word takes at least one byte
    return n <= (bytes_.size() - pos_) / static_cast<std::uint64_t>(size_of(type));
  }

  // Ends the instance: an ascii line must hold nothing more.
  void end() {
    if (format_ == Format::ascii && !words_.at_end())
      ascii_malformed(what() + " has more values than its properties");
  }

  // After the last element: nothing but blanks (ascii) or nothing at all (binary) may follow.
  void finish() {
    if (format_ == Format::ascii) {
      std::string_view line;
      while (lines_.next(line))
        if (!WordScanner(line).at_end())
          malformed("text after the last element (line " + std::to_string(line_number()) + ")");
    } else if (pos_ != bytes_.size()) {
      malformed(std::to_string(bytes_.size() - pos_) +
                " bytes follow the last element (the header announces less data than the file "
                "holds)");
    }
  }

  [[noreturn]] void truncated() const {
    std::ostringstream os;
    os << "PLY file is truncated: " << element_->name << " " << index_ << " of " << element_->count
       << " is incomplete";
    throw FormatError(os.str());
  }

  // The current instance is malformed: says which, and where in ascii.
  [[noreturn]] void instance_malformed(const std::string &why) const {
    malformed(what() + " " + why + location());
  }

private:
  std::string what() const { return element_->name + " " + std::to_string(index_); }
  long long line_number() const { return header_lines_ + lines_.number(); }
  std::string location() const {
    return format_ == Format::ascii ? " (line " + std::to_string(line_number()) + ")" : "";
  }
  [[noreturn]] void ascii_malformed(const std::string &what) const { malformed(what + location()); }

  std::string_view next_word() {
    std::string_view word;
    if (!words_.next(word))
      truncated();
    return word;
  }

  const char *take(int size) {
    if (bytes_.size() - pos_ < static_cast<std::size_t>(size))
      truncated();
    const char *p = bytes_.data() + pos_;
    pos_ += static_cast<std::size_t>(size);
    return p;
  }

  double decode(Scalar type, const char *p) const {
    const int size = size_of(type);
    std::uint64_t bits = 0;
    for (int i = 0; i < size; ++i) {
      const int byte = format_ == Format::binary_big_endian ? i : size - 1 - i;
      bits = bits << 8 | static_cast<unsigned char>(p[byte]);
    }
    switch (type) {
    case Scalar::int8:
      return static_cast<std::int8_t>(bits);
    case Scalar::uint8:
      return static_cast<std::uint8_t>(bits);
    case Scalar::int16:
      return static_cast<std::int16_t>(bits);
    case Scalar::uint16:
      return static_cast<std::uint16_t>(bits);
    case Scalar::int32:
      return static_cast<std::int32_t>(bits);
    case Scalar::uint32:
      return static_cast<std::uint32_t>(bits);
    case Scalar::float32: {
      const auto b32 = static_cast<std::uint32_t>(bits);
      float f;
      std::memcpy(&f, &b32, sizeof f);
      return f;
    }
    case Scalar::float64: {
      double d;
      std::memcpy(&d, &bits, sizeof d);
      return d;
    }
    }
    return 0;
  }

  std::string_view bytes_;
  Format format_;
  std::size_t pos_;   // binary: the next byte
  LineScanner lines_; // ascii: the body's lines
  long long header_lines_ = 0;
  WordScanner words_{""}; // ascii: the rest of the instance's line
  const Element *element_ = nullptr;
  std::uint64_t index_ = 0;
};

} // namespace

RawMesh parse_ply(std::string_view bytes) {
  const Header header = parse_header(bytes);
  const bool ascii = header.format == Format::ascii;
  require_text(bytes.substr(0, ascii ? bytes.size() : header.body),
               ascii ? "ASCII PLY file is not text" : "PLY header is not text");

  const Element *vertex = find_element(header, "vertex");
  if (!vertex)
    malformed("no \"element vertex\" in the header");
  int axis_of[3] = {-1, -1, -1}; // property index of x, y, z in the vertex element
  for (int axis = 0; axis < 3; ++axis) {
    const char *name[3] = {"x", "y", "z"};
    for (std::size_t k = 0; k < vertex->properties.size(); ++k)
      if (!vertex->properties[k].is_list && vertex->properties[k].name == name[axis])
        axis_of[axis] = static_cast<int>(k);
    if (axis_of[axis] < 0)
      malformed(std::string("the vertex element has no property ") + name[axis]);
  }
  const Element *face = find_element(header, "face");
  if (!face)
    malformed("no \"element face\" in the header");
  int indices_property = -1;
  for (const char *name : {"vertex_index", "vertex_indices"}) // the second wins if both
    for (std::size_t k = 0; k < face->properties.size(); ++k)
      if (face->properties[k].is_list && face->properties[k].name == name)
        indices_property = static_cast<int>(k);
  if (indices_property < 0)
    malformed("the face element has no vertex_indices list");
  const Property &indices = face->properties[static_cast<std::size_t>(indices_property)];
  if (!is_integer(indices.value_type))
    malformed("the face element's " + indices.name +
              " list holds floating-point values; vertex indices must have an integer type");
  if (vertex->count > static_cast<std::uint64_t>(INT_MAX))
    malformed("the header announces " + std::to_string(vertex->count) +
              " vertices, more than this reader can index");
  const auto num_vertices = static_cast<long long>(vertex->count);

  RawMesh raw;
  std::vector<int> face_corners;             // every face's indices, one face after another
  std::vector<std::size_t> face_begin = {0}; // where each face starts in face_corners
  BodyReader body(bytes, header);
  for (const Element &e : header.elements) {
    const bool is_vertex = &e == vertex, is_face = &e == face;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      body.begin(e, i);
      double xyz[3] = {0, 0, 0};
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const Property &p = e.properties[k];
        if (!p.is_list) {
          const double value = body.value(p.value_type);
          for (int axis = 0; axis < 3; ++axis)
            if (is_vertex && axis_of[axis] == static_cast<int>(k))
              xyz[axis] = value;
          continue;
        }
        const long long n = body.integer(p.count_type);
        if (n < 0)
          body.instance_malformed("has a list of negative length " + std::to_string(n));
        if (!is_face || static_cast<int>(k) != indices_property) {
          body.skip(p.value_type, static_cast<std::uint64_t>(n));
          continue;
        }
        if (n < 3)
          body.instance_malformed("has " + std::to_string(n) +
                                  " vertex indices (a face needs at least 3)");
        if (!body.can_hold(p.value_type, static_cast<std::uint64_t>(n)))
          body.truncated();
        for (long long c = 0; c < n; ++c) {
          const long long index = body.integer(p.value_type);
          if (index < 0 || index >= num_vertices)
            body.instance_malformed("refers to vertex " + std::to_string(index) +
                                    ", but there are " + std::to_string(num_vertices) +
                                    " vertices");
          face_corners.push_back(static_cast<int>(index));
        }
        face_begin.push_back(face_corners.size());
      }
      body.end();
      if (is_vertex)
        raw.points.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
  }
  body.finish();

  std::vector<int> corners;
  for (std::size_t f = 0; f + 1 < face_begin.size(); ++f) {
    corners.assign(face_corners.begin() + static_cast<std::ptrdiff_t>(face_begin[f]),
                   face_corners.begin() + static_cast<std::ptrdiff_t>(face_begin[f + 1]));
    const std::string why = append_face(raw, corners);
    if (!why.empty())
      malformed("face " + std::to_string(f) + " cannot be split into triangles: " + why);
  }
  return raw;
}

} // namespace tri::mesh_io
