// Internal to the mesh reader (mesh_reader.h states the contract): what the per-format parsers
// (stl_reader.cpp, obj_reader.cpp, ply_reader.cpp) hand to read_mesh_file, and the two steps
// they share (raw_mesh.cpp): splitting a polygon into triangles, and turning the triangles into
// an indexed mesh with exactly equal vertices merged.
#pragma once

#include "geometry/triangle_mesh.h"

#include <Eigen/Core>
#include <array>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tri::mesh_io {

// A parser's complaint about the bytes it was given. It does not name the file: read_mesh_file
// turns it into a MeshFileError "<path>: <message>".
class FormatError : public std::runtime_error {
public:
  explicit FormatError(const std::string &message) : std::runtime_error(message) {}
};

// Triangles as the file has them: `points` in the file's order (an STL gives three per
// triangle), `triangles` index them, in the file's order and with the file's corner order.
// Not yet checked for finite coordinates; points no triangle uses are allowed.
struct RawMesh {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
};

// Parsers: the whole content of a file of that format. Each throws FormatError for anything
// malformed, never returns a triangle whose index is out of range, and allocates only in
// proportion to what the bytes hold (never to a count the file merely announces).
RawMesh parse_stl(std::string_view bytes);
RawMesh parse_obj(std::string_view bytes);
RawMesh parse_ply(std::string_view bytes);

// Appends the face whose corners are `corners` (indices into raw.points, at least three, in the
// face's order) as triangles with the face's orientation.
//   - a triangle is appended as it is (even if degenerate: make_shape names those);
//   - a polygon first loses each corner whose point exactly equals the one before it (cyclically;
//     "f 1 2 3 3" is a triangle written as a quad); if every triangle of the fan from its first
//     remaining corner, (c0, ck, ck+1), turns the same way as the polygon as a whole (its vector
//     area), that fan is appended: this is the case of every convex polygon, flat or slightly
//     warped;
//   - otherwise (a concave polygon, or three corners in a line) it is split by ear clipping in
//     the plane normal to its vector area, always clipping the first ear found going round from
//     its second corner (for a convex polygon that is the same fan).
// Returns an empty string on success, else why the polygon cannot be split (fewer than three
// distinct corners, no area, not a simple polygon, or too many corners for ear clipping).
std::string append_face(RawMesh &raw, const std::vector<int> &corners);

// The indexed mesh of `raw`'s triangles: a vertex per distinct point (exactly equal coordinates,
// compared as numbers, so -0 equals 0) in the order the triangles first use them; points no
// triangle uses are dropped. Throws FormatError for a corner with a coordinate that is not
// finite, for no triangles at all, and for more vertices or triangles than an int indexes.
TriangleMesh index_triangles(const RawMesh &raw);

} // namespace tri::mesh_io
