// Checks that an indexed triangle mesh bounds a solid that a particle can be made of.
//
// A mesh passes when, in this order (the first failure is reported):
//   1. it has at least 4 triangles and every index names an existing vertex;
//   2. every vertex coordinate is finite (no NaN / inf);
//   3. no triangle is degenerate: no vertex used twice, and twice its area is at least
//      kDegenerateAreaTolerance * L^2, L = mesh_length_scale(mesh);
//   4. it is closed and edge-manifold: every undirected edge belongs to exactly two triangles;
//   5. it is consistently oriented: the two triangles of each edge traverse it in opposite
//      directions (so the surface is orientable and all normals agree);
//   6. it is one connected piece (edge-connected);
//   7. it is outward: the signed volume is above kFlatVolumeTolerance * L^3 (positive volume
//      with counter-clockwise triangles seen from outside; negative means inside-out).
// Not checked: self-intersection, and pinched vertices (two sheets touching at one vertex).
//
// Failures throw tri::ShapeError whose message names the problem and the triangle, edge
// or vertex index (0-based, as in TriangleMesh), e.g.
//   "mesh is not closed: edge (3, 7) of triangle 12 belongs to no other triangle (a hole)".
// Units: any (the tolerances are relative to the mesh's own size).
#pragma once

#include "geometry/triangle_mesh.h"

namespace tri {

// Relative tolerances of the checks above.
constexpr double kDegenerateAreaTolerance = 1e-10; // |cross product| / L^2
constexpr double kFlatVolumeTolerance = 1e-10;     // signed volume / L^3

// Length scale of the relative tolerances: the diagonal of the axis-aligned bounding box
// of all vertices (0 for an empty mesh).
double mesh_length_scale(const TriangleMesh &mesh);

// Throws ShapeError on the first problem found; returns normally for a valid mesh.
void validate_mesh(const TriangleMesh &mesh);

} // namespace tri
