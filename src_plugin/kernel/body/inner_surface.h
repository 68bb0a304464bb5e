// The inner surface: a particle's mesh offset inward by its soft layer, the surface the contact
// kernel measures. Two particles touch when their inner surfaces come within the sum of their
// layers, which is when their given surfaces (the meshes as the user gave them) touch: the
// given surface is the contact surface, as a sphere's radius is, and a bed packs as the meshes
// do. Mass, inertia, reach and output keep the given mesh.
//
// The offset. Every vertex p moves by the shortest displacement d that puts it at least
// `layer` behind the plane of each face around it: minimise |d| subject to n_f . d <= -layer
// for the distinct unit normals n_f of its triangles. In 3D the optimum has at most three
// active constraints, so every subset of one to three normals is solved as equalities and the
// shortest feasible solution kept: exact, no iteration. Triangles keep their vertices'
// indices, so the inner mesh has the given mesh's triangles in the same order.
//
// What the contact surface then is (the inner mesh grown by `layer`):
// - a convex shape whose vertices each join at most three face planes, or whose vertices are
//   symmetric (a cube, tetrahedron, octahedron, dodecahedron, icosahedron): every face plane
//   moved in by exactly `layer`, so the contact surface is the given shape with its edges and
//   corners rounded with radius `layer` (a sphero-polyhedron), inside the given one;
// - a vertex joining more than three planes without symmetry (a random rock's, an icosphere's):
//   every face around it at least `layer` behind its plane at that vertex, some by a little
//   more, so its facets tilt inward by at most the spread of the neighbouring normals times
//   `layer`: the contact surface lies on or inside the given surface;
// - a non-convex shape: the same rule at every vertex, concave ones included (they move into
//   the solid along their faces' normals). It holds while every feature is at least 2 layer
//   thick; the offset then keeps every vertex at least `layer` from the whole given surface.
//
// Failure (ShapeError, the message names the vertex or triangle and the layer that would fit):
// a vertex whose faces admit no such displacement (a knife edge), an inner triangle turned
// over against its given one, or an inner vertex closer than `layer` to any part of the given
// surface (a feature thinner than 2 layer: a plate, a tooth, a thin prism).
#pragma once

#include "geometry/triangle_mesh.h"

#include <Eigen/Core>
#include <vector>

namespace tri {

// Relative slack of the checks: a vertex counts as `layer` behind a plane or the surface when
// it is at least (1 - kInnerSurfaceTolerance) layer away (rounding of the 3x3 solves).
constexpr double kInnerSurfaceTolerance = 1e-6;

// The shortest d with n . d <= -layer for every n of `normals` (unit vectors), or false when
// no d satisfies them all. Near-parallel normals (within 1e-12) count once.
bool shortest_inward_offset(const std::vector<Eigen::Vector3d> &normals, double layer,
                            Eigen::Vector3d &d);

// The mesh with every vertex offset inward by `layer` (m, >= 0; 0 returns the mesh unchanged).
// Precondition: a valid closed, outward-oriented mesh (validate_mesh). Throws ShapeError as
// above.
TriangleMesh inner_surface(const TriangleMesh &mesh, double layer);

// The largest layer, of the halvings of `layer`, that inner_surface accepts (0 when none of
// 30 does): what an error message proposes instead.
double largest_fitting_layer(const TriangleMesh &mesh, double layer);

} // namespace tri
