// The contact patch of two nearly parallel triangles: where, and how strongly, two flat faces
// of two particles (or a particle and a wall) press on each other through their soft layers.
// contact_reduction.h places a contact point at the centre of the union of these patches.
//
// Why. Where two faces are parallel every point of their overlap is a closest point, and the
// distance kernel returns one arbitrary closest pair (often a vertex): the midpoint of that pair
// says nothing about where the faces touch. The patch below is computed from the triangles
// themselves, so the union of the patches of all triangle pairs of two faces is the overlap of
// the two faces, whatever their meshes (the triangles of a face partition it).
//
// Geometry. Let n_a, n_b be the unit normals of the triangles (vertex order does not matter),
// and m = (n_a + sign(n_a . n_b) n_b) normalised, oriented so that m . normal > 0, `normal`
// being the contact normal from a towards b. Both triangles are projected along m onto the
// plane orthogonal to m and the projection of b is clipped against that of a (Sutherland-
// Hodgman; a convex polygon of at most 6 vertices). Over that polygon the gap along m,
// g(x) = h_b(x) - h_a(x) (h: height of each triangle's plane along m), is affine, and so is
// the local overlap o(x) = layer - g(x); the polygon is clipped once more to o >= 0 (at most
// 7 vertices). With the polygon P:
//   area     = |P|                       (m^2, measured in the plane orthogonal to m)
//   weight   = integral over P of o dA   (m^3): the load of a penalty proportional to the
//              local overlap; for parallel faces o is uniform and weight = o * area
//   centroid = (integral of o x dA) / weight, lifted to the mid-surface between the two planes
//              (height (h_a + h_b) / 2 along m): the centre of pressure. For parallel faces it
//              is the centroid of the overlap region; for faces tilted by a small angle it
//              moves towards the side where they press harder (a restoring torque).
//   area_centroid, second_moment = the centroid of P (lifted to the mid-surface likewise) and
//              its second moment of area about that centroid, J = integral of r r^T dA,
//              r = x - area_centroid in the plane orthogonal to m (m^4, a symmetric 3x3 tensor in
//              the world frame, rank 2, J m = 0; trace J = the polar moment). Exact for the
//              polygon, from the fan formula integral over a triangle (0, d1, d2) of x x^T dA =
//              A/12 (d1 d1^T + d2 d2^T + (d1 + d2)(d1 + d2)^T), shifted to the centroid.
//              Geometric only (independent of the overlap o): it is what a dashpot spread
//              uniformly over the patch needs to resist rocking (contact_reduction.h, step 6).
// A pair whose planes cross inside the polygon (intersecting triangles) is handled by the same
// formula: o keeps growing past the crossing, as the reduction's overlap does.
//
// When a pair counts as "nearly parallel": |n_a . n_b| >= cos(kParallelFaceAngle). 10 degrees:
// far below the angle of any edge or vertex contact of a convex particle's faces that the
// reduction must keep as it is (those faces meet the other surface at a clear angle), and far
// above the tilt of a face resting on another (a 4 mm cube lifts an edge off the plane at
// about 2 degrees of tilt). Below the threshold a tilted face's patch is the wedge where the
// layers overlap, of width at most layer / tan(10 deg) = 5.7 layer, so switching to the
// midpoint rule above it moves the contact point by less than that.
//
// Degenerate input: a triangle of zero area has no normal and gives `false`; so does a pair
// that is not nearly parallel. Touching projections (a shared edge) give area 0 up to
// rounding; the caller treats area <= kPatchAreaRounding * (smaller triangle's area) as 0.
// Units: those of the input; the result is computed relative to a vertex of triangle a, so it
// is scale-free. No allocation.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tri {

constexpr double kParallelFaceAngle = 0.17453292519943295; // rad, 10 degrees
constexpr double kPatchAreaRounding = 1e-9; // patch area below this fraction: touching only

struct ContactPolygon {
  double area = 0.0;   // m^2, area of the patch (projected along m)
  double weight = 0.0; // m^3, integral of the local overlap over the patch; >= 0
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(); // m, centre of pressure on the
                                                      // mid-surface (meaningful if weight > 0)
  double min_triangle_area = 0.0; // m^2, the smaller of the two triangles' areas
  Eigen::Vector3d area_centroid = Eigen::Vector3d::Zero(); // m, centroid of the patch's area
                                                           // on the mid-surface (if area > 0)
  Eigen::Matrix3d second_moment = Eigen::Matrix3d::Zero(); // m^4, integral of r r^T dA about
                                                           // area_centroid, r orthogonal to m
  double polar_moment() const { return second_moment.trace(); } // m^4
};

// Patch of triangle a = (a0, a1, a2) and triangle b = (b0, b1, b2) under a soft layer of
// width `layer` (eps_a + eps_b, m), `normal` the contact normal from a towards b (any non-zero
// vector on the right side; only its sign relative to the faces is used). Returns false, and
// leaves `patch` zero (default), when the triangles are not nearly parallel or one is degenerate.
bool contact_polygon(const Eigen::Vector3d &a0, const Eigen::Vector3d &a1,
                     const Eigen::Vector3d &a2, const Eigen::Vector3d &b0,
                     const Eigen::Vector3d &b1, const Eigen::Vector3d &b2,
                     const Eigen::Vector3d &normal, double layer, ContactPolygon &patch);

} // namespace tri
