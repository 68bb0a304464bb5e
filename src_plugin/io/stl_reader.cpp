// STL, binary and ASCII (the contract is in mesh_reader.h).
//
// Binary: an 80-byte header, a little-endian uint32 triangle count, then 50 bytes per triangle
// (normal, three corners as 12 little-endian float32, a 2-byte attribute count). ASCII:
//   solid [name]
//     facet normal nx ny nz          (any number of facets)
//       outer loop
//         vertex x y z               (exactly three)
//       endloop
//     endfacet
//   endsolid [name]                  (then possibly further solids)
// with keywords in any case. The facet normal and the attribute bytes are not read (normals
// follow from the corners' order); "color ..." lines between facets, which some exporters
// write, are skipped.
#include "mesh_formats.h"
#include "text_scanner.h"

#include <cctype>
#include <climits>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace tri::mesh_io {

namespace {

constexpr std::uint64_t kBinaryHeaderBytes = 84, kBinaryTriangleBytes = 50;

std::uint32_t little_endian_u32(const char *bytes) {
  const auto *b = reinterpret_cast<const unsigned char *>(bytes);
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
         std::uint32_t(b[3]) << 24;
}

float little_endian_f32(const char *bytes) {
  const std::uint32_t bits = little_endian_u32(bytes);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

bool starts_with_solid(std::string_view bytes) {
  std::size_t i = 0;
  while (i < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[i])))
    ++i;
  return lowercase(bytes.substr(i, 5)) == "solid";
}

RawMesh parse_binary_stl(std::string_view bytes, std::uint64_t count) {
  if (count > static_cast<std::uint64_t>(INT_MAX / 3))
    throw FormatError("binary STL has more triangles than this reader can index");
  RawMesh raw;
  raw.points.reserve(3 * count); // the file holds them all: its size was checked
  raw.triangles.reserve(count);
  for (std::uint64_t t = 0; t < count; ++t) {
    const char *corners = bytes.data() + kBinaryHeaderBytes + kBinaryTriangleBytes * t + 12;
    const int first = static_cast<int>(raw.points.size());
    for (int k = 0; k < 3; ++k) {
      const char *c = corners + 12 * k;
      raw.points.emplace_back(little_endian_f32(c), little_endian_f32(c + 4),
                              little_endian_f32(c + 8));
    }
    raw.triangles.push_back({first, first + 1, first + 2});
  }
  return raw;
}

// The first word of the last line that is not blank, in lower case.
std::string last_keyword(std::string_view bytes) {
  std::size_t end = bytes.size();
  while (end > 0 && (is_blank(bytes[end - 1]) || bytes[end - 1] == '\n'))
    --end;
  const std::size_t newline = end == 0 ? std::string_view::npos : bytes.rfind('\n', end - 1);
  const std::size_t begin = newline == std::string_view::npos ? 0 : newline + 1;
  WordScanner words(bytes.substr(begin, end - begin));
  std::string_view word;
  return words.next(word) ? lowercase(word) : std::string();
}

RawMesh parse_ascii_stl(std::string_view text) {
  const std::string truncated =
      "ASCII STL is truncated or malformed: no \"endsolid\" line at its end";
  // Said first, as the likeliest reason for what follows: a file cut short.
  if (last_keyword(text) != "endsolid")
    throw FormatError(truncated);

  enum class Expect { solid, facet, outer_loop, vertex, endloop, endfacet };
  Expect expect = Expect::solid;
  RawMesh raw;
  LineScanner lines(text);
  std::string_view line, word;
  auto malformed = [&](const std::string &what) {
    std::ostringstream os;
    os << "ASCII STL is malformed: " << what << " (line " << lines.number() << ")";
    throw FormatError(os.str());
  };
  auto expected = [&](const char *what) {
    malformed(std::string("expected ") + what + ", found " + quoted(line));
  };
  double corner[3];
  int corners_read = 0;
  while (lines.next(line)) {
    WordScanner words(line);
    if (!words.next(word))
      continue;
    const std::string keyword = lowercase(word);
    switch (expect) {
    case Expect::solid:
      if (keyword != "solid")
        expected("\"solid\"");
      expect = Expect::facet; // the name, if any, is not needed
      break;
    case Expect::facet:
      if (keyword == "facet")
        expect = Expect::outer_loop; // the normal is not read
      else if (keyword == "endsolid")
        expect = Expect::solid;
      else if (keyword != "color")
        expected("\"facet\" or \"endsolid\"");
      break;
    case Expect::outer_loop:
      if (keyword != "outer" || !words.next(word) || lowercase(word) != "loop" || !words.at_end())
        expected("\"outer loop\"");
      expect = Expect::vertex;
      corners_read = 0;
      break;
    case Expect::vertex:
      if (keyword != "vertex")
        expected("\"vertex\"");
      for (double &x : corner) {
        if (!words.next(word))
          malformed("a vertex needs three coordinates x y z");
        const NumberParse outcome = parse_double(word, x);
        if (outcome != NumberParse::ok)
          malformed(number_complaint(word, outcome, "a number"));
      }
      if (!words.at_end())
        malformed("a vertex has more than three coordinates");
      if (raw.points.size() >= static_cast<std::size_t>(INT_MAX))
        malformed("more corners than this reader can index");
      raw.points.emplace_back(corner[0], corner[1], corner[2]);
      if (++corners_read == 3) {
        const int first = static_cast<int>(raw.points.size()) - 3;
        raw.triangles.push_back({first, first + 1, first + 2});
        expect = Expect::endloop;
      }
      break;
    case Expect::endloop:
      if (keyword != "endloop" || !words.at_end())
        expected("\"endloop\" after three vertices");
      expect = Expect::endfacet;
      break;
    case Expect::endfacet:
      if (keyword != "endfacet" || !words.at_end())
        expected("\"endfacet\"");
      expect = Expect::facet;
      break;
    }
  }
  if (expect != Expect::solid)
    throw FormatError(truncated);
  return raw;
}

} // namespace

RawMesh parse_stl(std::string_view bytes) {
  // Binary is recognised by its size, since CAD exporters may start a binary header with
  // "solid" too; then by binary data's zero bytes (attribute counts, zero normal components),
  // which ASCII text never has.
  if (bytes.size() >= kBinaryHeaderBytes) {
    const std::uint64_t count = little_endian_u32(bytes.data() + 80);
    const std::uint64_t size = kBinaryHeaderBytes + kBinaryTriangleBytes * count;
    if (bytes.size() == size)
      return parse_binary_stl(bytes, count);
    const bool has_zero_byte = bytes.find('\0', kBinaryHeaderBytes) != std::string_view::npos;
    if (!starts_with_solid(bytes) || has_zero_byte) {
      std::ostringstream os;
      os << "binary STL is truncated or malformed: its header announces " << count << " triangles ("
         << size << " bytes) but the file has " << bytes.size() << " bytes";
      throw FormatError(os.str());
    }
  } else if (!starts_with_solid(bytes)) {
    std::ostringstream os;
    os << "not an STL file: " << bytes.size()
       << " bytes is too short for a binary STL (84-byte header) and it does not start with "
          "\"solid\" (ASCII STL)";
    throw FormatError(os.str());
  }
  require_text(bytes, "STL file is neither binary (its size is not 84 + 50 x its triangle count) "
                      "nor ASCII text");
  return parse_ascii_stl(bytes);
}

} // namespace tri::mesh_io
