// Reads a closed triangle mesh from a file, for `shape NAME file PATH` (see DESIGN.md).
//
// Formats, chosen by the extension (case-insensitive), read by VTK's readers:
//   .stl  ASCII or binary (vtkSTLReader). Binary is recognised by its size
//         (84 + 50 x the triangle count in the header), even if the header starts with
//         "solid"; otherwise a file starting with "solid" is ASCII.
//   .obj  Wavefront OBJ (vtkOBJReader): vertices and faces; texture and normal data ignored.
//   .ply  ASCII or binary PLY (vtkPLYReader).
// Faces with more than three corners (OBJ, PLY) are triangulated (vtkTriangleFilter); points
// and lines in the file are ignored. Vertices with exactly equal coordinates are merged, so
// an STL (which repeats each corner in every triangle) becomes an indexed mesh; no tolerance
// is applied, which is right for files whose shared corners were written from the same
// numbers. Units: the file's, unchanged (apply `scaled` for another unit).
// Precision: VTK's three readers keep points as 32-bit floats whatever the file holds, so
// coordinates carry about 7 significant digits (relative error <= 6e-8).
//
// The result is not validated beyond finite coordinates: closedness, orientation and
// degeneracy are make_shape's job (shape.h), which names the offending triangle.
//
// Errors throw MeshFileError whose message starts with "<path>: ", for: a missing, unreadable
// or empty file; an unknown extension; a binary STL whose size disagrees with its triangle
// count; an ASCII STL without its closing "endsolid" or with a byte that is not ASCII text
// (VTK would take it for binary); a PLY file whose body is shorter than its header announces
// or whose faces name missing vertices, or without vertex x, y, z or face vertex_indices
// (checked before VTK reads it: VTK 9.1's PLY reader aborts the process on a truncated file
// and dereferences a missing element); an OBJ face naming a vertex, texture coordinate or
// normal not defined before it, or mixing corner forms (checked before VTK reads it, which
// uses the indices unchecked); anything VTK reports as an error or warning while reading
// (captured, never printed); a file with no triangles; a coordinate that is not finite as a
// 32-bit float (1e39, nan, inf).
// Thread safety: calls are serialised internally (VTK's message window is process-global).
#pragma once

#include "triangle_mesh.h"

#include <stdexcept>
#include <string>

namespace tri {

class MeshFileError : public std::runtime_error {
public:
  explicit MeshFileError(const std::string &message) : std::runtime_error(message) {}
};

TriangleMesh read_mesh_file(const std::string &path);

} // namespace tri
