// Convex random rocks: the triangulated convex hull of random points on an ellipsoid.
//
// Method: n = (ntri + 4) / 2 random directions on the unit sphere, spread so that no two are
// closer (chord) than kRockMinSpacing x the edge of a regular hexagonal tiling of the
// sphere by n points; their convex hull (Qhull, triangulated) has exactly 2n - 4 = ntri
// triangles when every point is a hull vertex, which holds for points in general position on
// a sphere. A draw is rejected, and the next one taken from the same random stream, when the
// hull has another triangle count or a sliver: a triangle angle below kRockMinAngleDegrees,
// an edge shorter than kRockMinSpacing x the tiling edge, or an interior dihedral angle below
// kRockMinDihedralDegrees (a wedge: e.g. a flat tetrahedron from four points near one great
// circle), all measured on the sphere.
// The hull is then stretched by (1, aspect_middle, aspect_short) along x, y, z (an affine map
// keeps it convex with the same triangles; it can make angles smaller, by at most a factor of
// about aspect_short), triangles are oriented outward (counter-clockwise seen from outside),
// the mesh is translated so that its centre of mass (solid, uniform density) is the origin
// and scaled so that 2 x (largest vertex distance from the centre of mass) == size.
//
// Determinism: the result depends only on the parameters. Random numbers come from
// std::mt19937_64 (whose raw output the C++ standard fixes) mapped to [0, 1) by our own code
// (std:: distributions differ between standard libraries); triangles are listed in a
// canonical order (each starting at its smallest vertex index, then sorted), so the result
// does not depend on Qhull's internal facet order either.
#pragma once

#include "geometry/triangle_mesh.h"

#include <cstdint>

namespace tri {

struct RockParameters {
  int ntri = 20;     // number of triangles: even, >= 4
  double size = 1.0; // bounding diameter = 2 x max vertex distance from the centre of mass, m
  std::uint64_t seed = 0;
  double aspect_middle = 1.0; // middle / long axis ratio, in (0, 1]
  double aspect_short = 1.0;  // short / long axis ratio, in (0, 1]; <= aspect_middle not required
};

constexpr double kRockMinSpacing = 0.5;          // fraction of the hexagonal tiling edge
constexpr double kRockMinAngleDegrees = 10.0;    // smallest triangle angle on the sphere
constexpr double kRockMinDihedralDegrees = 30.0; // smallest interior dihedral angle on the sphere
constexpr int kRockMaxAttempts = 10000;          // draws before giving up (never reached in tests)

// Throws ShapeError for ntri odd or < 4, size not positive and finite, aspect outside (0, 1],
// or (not expected) no acceptable hull within kRockMaxAttempts draws.
TriangleMesh random_rock(const RockParameters &params);

} // namespace tri
