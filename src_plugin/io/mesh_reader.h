// Reads a closed triangle mesh from a file, for `shape NAME file PATH` of fix tri/particles.
//
// Formats, chosen by the extension (case-insensitive), each read by a parser of its own
// (stl_reader.cpp, obj_reader.cpp, ply_reader.cpp; no VTK):
//   .stl  binary or ASCII. Binary is recognised by its size (84 + 50 x the triangle count in
//         its header), even if the header starts with "solid"; otherwise a file starting with
//         "solid" is ASCII (keywords in any case; several solids in a row are one mesh). Facet
//         normals and attribute bytes are not read.
//   .obj  Wavefront OBJ: "v" and "f" lines. Corners v, v/vt, v//vn or v/vt/vn (one form per
//         face), 1-based or negative (counting back from the last one defined before the face);
//         texture and normal indices are checked against the "vt"/"vn" lines before the face
//         and otherwise ignored. Other records (l, p, g, o, usemtl, s, comments, ...) are
//         skipped.
//   .ply  ascii, binary_little_endian or binary_big_endian: the vertex element's x, y, z (any
//         scalar type) and the face element's vertex_indices (or vertex_index) list; other
//         elements and properties are skipped by their declared types.
// Faces with more than three corners (OBJ, PLY) are split into triangles with their
// orientation: a convex polygon into the fan from its first corner (c0, ck, ck+1), any other
// simple polygon (concave, or with three corners in a line) by ear clipping (mesh_formats.h);
// consecutive corners at the same point count once. Vertices with exactly equal coordinates
// are merged (so an STL, which repeats each corner in every triangle, becomes an indexed
// mesh), in the order the triangles first use them; vertices no triangle uses are dropped.
// No tolerance is applied, which is right for files whose shared corners were written from the
// same numbers. Units: the file's, unchanged (apply `scaled` for another unit).
// Precision: what the file holds. Text numbers (ASCII STL, OBJ, ASCII PLY) are parsed as
// doubles, correctly rounded as by strtod and independent of the locale; binary STL holds
// float32; binary PLY values are converted exactly from their declared type (float, double or
// an integer type).
//
// The result is not validated beyond finite coordinates: closedness, orientation and
// degeneracy are make_shape's job (shape.h), which names the offending triangle.
//
// Errors throw MeshFileError whose message is "<path>: <what>", for: a missing, unreadable or
// empty file; an unknown extension; a binary STL whose size disagrees with its triangle count;
// an ASCII STL without its closing "endsolid", with a byte that is not ASCII text, or with a
// line out of place (named with its number); an OBJ line that is not what its keyword needs (a
// vertex without three numbers, a face with fewer than three corners, a corner that is not an
// index, mixes corner forms or names a vertex, texture coordinate or normal not defined before
// it); a PLY file whose header is malformed (unknown format or type, no vertex x/y/z or face
// vertex index list, stray lines), whose body is shorter or longer than its header announces,
// whose ascii values are not numbers, or whose faces name vertices that do not exist or have
// fewer than three; a face that is not a simple polygon; a number beyond the range of a double;
// a file with no triangles; a triangle corner with a coordinate that is not finite (nan, inf).
// No count a file announces is trusted with an allocation before the bytes behind it are seen.
// Thread safety: calls are independent (no shared state).
#pragma once

#include "geometry/triangle_mesh.h"

#include <stdexcept>
#include <string>

namespace tri {

class MeshFileError : public std::runtime_error {
public:
  explicit MeshFileError(const std::string &message) : std::runtime_error(message) {}
};

TriangleMesh read_mesh_file(const std::string &path);

} // namespace tri
