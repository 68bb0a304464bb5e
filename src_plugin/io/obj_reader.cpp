// Wavefront OBJ (the contract is in mesh_reader.h). Read: "v x y z" lines (a fourth number w,
// or a colour r g b [a] after the coordinates, is allowed and ignored) and "f" lines, whose
// corners are v, v/vt, v//vn or v/vt/vn, one form throughout a face. An index is 1-based, or
// negative to count back from the last element of its kind defined before the line (-1 is the
// last). Texture coordinates ("vt") and normals ("vn") are only counted, so that the indices
// that faces give them can be checked. Everything else (comments, groups, objects, materials,
// smoothing groups, "l" lines and "p" points, free-form geometry) is no part of a closed
// surface and is skipped.
#include "mesh_formats.h"
#include "text_scanner.h"

#include <algorithm>
#include <climits>
#include <sstream>

namespace tri::mesh_io {

namespace {

// v, vt and vn: what a face corner refers to.
constexpr const char *kKindNames[3] = {"vertex", "texture coordinate", "normal"};
constexpr const char *kKindPlurals[3] = {"vertices", "texture coordinates", "normals"};

} // namespace

RawMesh parse_obj(std::string_view text) {
  RawMesh raw;
  long long defined[3] = {0, 0, 0}; // v, vt and vn lines so far
  long long face = 0;               // f lines so far
  std::vector<int> corners;
  LineScanner lines(text);
  std::string_view line, keyword, word;
  auto malformed = [&](const std::string &what) {
    std::ostringstream os;
    os << "mesh file is malformed: " << what << " (line " << lines.number() << ")";
    throw FormatError(os.str());
  };
  while (lines.next(line)) {
    WordScanner words(line);
    if (!words.next(keyword))
      continue;
    if (keyword == "v") {
      double coordinate[3];
      for (double &x : coordinate) {
        if (!words.next(word))
          malformed("a vertex needs three coordinates x y z");
        const NumberParse outcome = parse_double(word, x);
        if (outcome != NumberParse::ok)
          malformed(number_complaint(word, outcome, "a number"));
      }
      int extra = 0; // w, or a colour r g b [a]
      for (double ignored; words.next(word); ++extra) {
        const NumberParse outcome = parse_double(word, ignored);
        if (outcome != NumberParse::ok)
          malformed(number_complaint(word, outcome, "a number"));
      }
      if (extra > 4)
        malformed("a vertex has more than seven numbers (x y z, then w or a colour r g b [a])");
      if (raw.points.size() >= static_cast<std::size_t>(INT_MAX))
        malformed("more vertices than this reader can index");
      raw.points.emplace_back(coordinate[0], coordinate[1], coordinate[2]);
      ++defined[0];
    } else if (keyword == "vt") {
      ++defined[1];
    } else if (keyword == "vn") {
      ++defined[2];
    } else if (keyword == "f") {
      const long long f = face++;
      auto bad_face = [&](const std::string &why) {
        malformed("face " + std::to_string(f) + " " + why);
      };
      corners.clear();
      int form = -1; // v, v/vt, v//vn, v/vt/vn
      while (words.next(word)) {
        const auto slashes = std::count(word.begin(), word.end(), '/');
        if (slashes > 2)
          bad_face("has a corner with more than two slashes: " + quoted(word));
        const std::size_t slash1 = word.find('/');
        const std::size_t slash2 = slashes == 2 ? word.find('/', slash1 + 1) : word.npos;
        std::string_view fields[3] = {word.substr(0, slash1)};
        if (slashes >= 1)
          fields[1] = word.substr(slash1 + 1, slashes == 2 ? slash2 - slash1 - 1 : word.npos);
        if (slashes == 2)
          fields[2] = word.substr(slash2 + 1);
        if (fields[0].empty() || (slashes == 1 && fields[1].empty()) ||
            (slashes == 2 && fields[2].empty()))
          bad_face("has a corner with an index missing: " + quoted(word));
        const int this_form = static_cast<int>(slashes) + 3 * !fields[1].empty();
        if (form >= 0 && this_form != form)
          bad_face("mixes the corner forms v, v/vt, v//vn and v/vt/vn: " + quoted(word));
        form = this_form;
        for (int kind = 0; kind < 3; ++kind) {
          if (fields[kind].empty())
            continue;
          long long index = 0;
          const NumberParse outcome = parse_integer(fields[kind], index);
          if (outcome == NumberParse::not_a_number)
            bad_face("has a corner " + quoted(word) + " whose " + kKindNames[kind] +
                     " index is not an integer");
          const long long count = defined[kind];
          const bool in_range = outcome == NumberParse::ok &&
                                ((index >= 1 && index <= count) || (index < 0 && index >= -count));
          if (!in_range) {
            std::ostringstream os;
            os << "refers to " << kKindNames[kind] << " " << fields[kind]
               << " (1-based), but there are " << count << " "
               << (count == 1 ? kKindNames[kind] : kKindPlurals[kind]) << " before it";
            bad_face(os.str());
          }
          if (kind == 0)
            corners.push_back(static_cast<int>(index > 0 ? index - 1 : count + index));
        }
      }
      if (corners.size() < 3)
        bad_face("has " + std::to_string(corners.size()) + " corners (a face needs at least 3)");
      const std::string why = append_face(raw, corners);
      if (!why.empty())
        bad_face("cannot be split into triangles: " + why);
    }
  }
  return raw;
}

} // namespace tri::mesh_io
