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
// the local overlap o(x) = layer - g(x) cos(phi / 2), phi the angle between the triangles
// (cos(phi / 2) = m . n_a = m . n_b): g cos(phi / 2) is the distance of a corner of either
// triangle from the other's plane, so where the closest points are a vertex over a face the
// largest o is the distance kernel's overlap, exactly (a vertex of an icosphere on a plane:
// along m alone it was short by 1e-3 of the gap, and restitution lost 1.6 %); the polygon is
// clipped once more to o >= 0 (at most 7 vertices). With the polygon P:
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
//   weight2  = integral over P of o^2 dA (m^4): with weight and area, the mean square overlap,
//              the energy of a penalty spread over the patch (contact_reduction.h step 5b)
//   corner_overlaps, max_overlap = o at each corner and the largest (o is affine on P, so the
//              largest overlap over P is at a corner): exact functions of the two triangles,
//              without the distance kernel's tolerance
//   corner_points, corner_distances = each corner's exact closest points on the two
//              triangles, their midpoint and distance: a corner is a vertex of one triangle over
//              the other (vertex to triangle) or the crossing of an edge of each (edge to edge),
//              known from the lines its two polygon edges lie on; what the distance kernel gives
//              for that feature pair, without its tolerance (contact_reduction.h step 5b)
//   direction = m, the direction areas are measured along; overlap_gradient = the gradient
//              of the affine o (orthogonal to m; zero for parallel triangles)
//   vertices = the polygon's corners on the mid-surface (world frame, counter-clockwise about
//              m), so that integrals that are not polynomial (the mean distance from a point that
//              is known only once all the patches of a contact are summed: the twisting-friction
//              lever of contact_reduction.h step 6) can be taken later.
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
constexpr double kCurvedFacetAngle = 0.7853981633974483; // rad, 45 degrees (step 5c)
constexpr double kPatchAreaRounding = 1e-9; // patch area below this fraction: touching only
// Sutherland-Hodgman on a convex polygon adds at most one vertex per half-plane, but rounding
// can make nearly collinear vertices alternate sides; each clip at most doubles the count (a
// vertex and a crossing per edge), so a triangle clipped by 4 half-planes never exceeds 48.
constexpr int kPolygonMaxVertices = 48;

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
  double weight2 = 0.0;     // m^4, integral of o^2 dA
  double max_overlap = 0.0; // m, largest local overlap (at a corner)
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ(); // unit, m (areas are measured along it)
  double cos_half_angle = 1.0; // cos(phi / 2) = m . n_a: gap along m times it is a distance
  Eigen::Vector3d normal_b = Eigen::Vector3d::UnitZ(); // unit, b's plane normal, m . normal_b > 0
  Eigen::Vector3d normal_a = Eigen::Vector3d::UnitZ(); // unit, a's plane normal, m . normal_a > 0
  Eigen::Vector3d overlap_gradient = Eigen::Vector3d::Zero(); // 1, of o along P (orthogonal to m)
  int num_vertices = 0; // corners of the patch (0 when area is 0)
  Eigen::Vector3d vertices[kPolygonMaxVertices]; // m, world frame, counter-clockwise about m
  double corner_overlaps[kPolygonMaxVertices];   // m, o at each corner, >= 0
  Eigen::Vector3d corner_points[kPolygonMaxVertices]; // m, each corner's contact point
  double corner_distances[kPolygonMaxVertices]; // m, its exact closest-point distance; -1 on
                                                // the layer's cut (o = 0 there)
  double polar_moment() const { return second_moment.trace(); } // m^4
};

// Patch of triangle a = (a0, a1, a2) and triangle b = (b0, b1, b2) under a soft layer of
// width `layer` (eps_a + eps_b, m), `normal` the contact normal from a towards b (any non-zero
// vector on the right side; only its sign relative to the faces is used). Returns false, and
// leaves `patch` zero (default), when the triangles are not nearly parallel or one is degenerate.
// `max_angle` (rad, < pi / 2): the angle up to which a pair counts as nearly parallel; the
// polygon is well defined up to any such angle, and contact_reduction.h's step 5c takes the
// moments of a curved patch over kCurvedFacetAngle (the rest of the reduction: 10 degrees).
bool contact_polygon(const Eigen::Vector3d &a0, const Eigen::Vector3d &a1,
                     const Eigen::Vector3d &a2, const Eigen::Vector3d &b0,
                     const Eigen::Vector3d &b1, const Eigen::Vector3d &b2,
                     const Eigen::Vector3d &normal, double layer, ContactPolygon &patch,
                     double max_angle = kParallelFaceAngle);

// The part of a patch where the local overlap exceeds `level` (m), weighted by the excess:
// weight = integral over P of (o - level)^+ dA (m^3) and moment = integral of
// (o - level)^+ (x - origin) dA (m^4), square = integral of ((o - level)^+)^2 dA (m^4), x on the
// polygon's corners' plane, areas along
// `direction`. Continuous in the geometry and in `level` (the deepest region of a face contact,
// tapered: contact_reduction.h step 5). Zero when max_overlap <= level.
struct ExcessIntegral {
  double weight = 0.0;                             // m^3
  Eigen::Vector3d moment = Eigen::Vector3d::Zero(); // m^4, about `origin`
  double square = 0.0;                             // m^4, integral of ((o - level)^+)^2 dA
};
ExcessIntegral excess_over(const ContactPolygon &patch, double level,
                           const Eigen::Vector3d &origin);

// The peak of a curved patch's overlap from its moments M1, M2, M3 (integrals of o, o^2, o^3
// over the patch, o = 0 on its border) and its gradient (contact_reduction.h, step 5c).
// For a profile o = D - f(x), f homogeneous of any degree k about the peak (f(s x) = s^k f(x):
// a cone k = 1, a wedge, a paraboloid k = 2, flat k -> infinity) in one or two dimensions,
// M_p = p c D^(a + p) B(a + 1, p), a = dim / k, so r1 = M2 / M1 = 2 D / (a + 2) and
// r2 = M3 / M2 = 3 D / (a + 3), and eliminating a:
//   peak = r1 r2 / (3 r1 - 2 r2) = M2 M3 / (3 M2^2 - 2 M1 M3)  = D exactly, for every such
// profile, without knowing k -- a vertex's cone, an edge's wedge and a ball's cap alike. It is
// an integral, so on a faceted ball it does not see which vertex is deepest: it is the smooth
// cap's peak, where the deepest vertex jumps from vertex to vertex and its lever turns with
// the ball. Rigid motion changes o by an affine do(x); with o = 0 on the border,
// dM_p = p M_(p-1) do(c_(p-1)) (c_0 the area centre, c_1 the centre of pressure, c_2 the
// centroid of o^2), so d peak = a_area do(c_0) + a_pressure do(c_1) + a_second do(c_2): the
// gradient acts at (sum a_i c_i) / (sum a_i); sum a_i = 1 for the profiles above (a uniform
// do raises the peak by do). t = M1 M3 / M2^2 is 1 (flat) to 1.2 (cone) for them and tends to
// 1.5 (where the denominator vanishes) only for a spike sharper than any convex corner;
// `validity` falls smoothly from 1 at t = 1.25 to 0 at 1.35, where the caller keeps the
// deepest point's law.
struct CurvedPeak {
  double peak = 0.0;                               // m
  double a_area = 0.0, a_pressure = 0.0, a_second = 0.0; // 1, the gradient's weights
  double validity = 0.0;                           // 1, see above
};
CurvedPeak curved_peak(double area, double m1, double m2, double m3);

// The moments of a patch's overlap o (affine on it; corner values corner_overlaps) with areas
// measured along one `normal` (unit) for all the polygons of a contact: each polygon's own
// direction m differs from its neighbours' by half their tilt, and moments taken along
// different directions do not add up to those of one field (a vertex's cone came out 1 % off
// its peak), and so are the corners' positions: the moments take each corner on a's surface.
// `layer`: the one the patch was made with. Positions relative to `origin` (m).
struct OverlapMoments {
  double area = 0.0, m1 = 0.0, m2 = 0.0, m3 = 0.0;  // m^2, m^3, m^4, m^5
  Eigen::Vector3d area1 = Eigen::Vector3d::Zero();   // integral of x dA, m^3
  Eigen::Vector3d first1 = Eigen::Vector3d::Zero();  // integral of o x dA, m^4
  Eigen::Vector3d second1 = Eigen::Vector3d::Zero(); // integral of o^2 x dA, m^5
  // Integrals of b's normal n_b times 1, o, o^2: a rigid translation d of b changes o by
  // -n_b . d (b's plane moves along its normal), so dM_p = -p (integral of o^(p-1) n_b) . d,
  // and the moments' peak is pushed along their weighted sum (a wall: its normal).
  Eigen::Vector3d area_normal = Eigen::Vector3d::Zero(); // m^2
  Eigen::Vector3d m1_normal = Eigen::Vector3d::Zero();   // m^3
  Eigen::Vector3d m2_normal = Eigen::Vector3d::Zero();   // m^4
  // Area integral of a's normal (how each surface turns over the patch: 1 - |mean normal|^2 is
  // the mean square deviation of a unit normal).
  Eigen::Vector3d area_normal_a = Eigen::Vector3d::Zero(); // m^2
};
void add_overlap_moments(const ContactPolygon &patch, double layer, const Eigen::Vector3d &normal,
                         const Eigen::Vector3d &origin, OverlapMoments &sum);

// Integrals over a planar polygon `v` (n corners, in order, either orientation), projected
// along `normal` (unit) onto the plane through `p` orthogonal to it, of 1 and of the distance
// from p: area (m^2) and integral of |x - p| dA (m^3); their ratio is the polygon's mean
// distance from p. Closed form per edge (a fan of signed triangles from p): for the edge's
// line at distance h from p, with t the position along the line from the foot of the
// perpendicular, integral over the triangle (p, t0, t1) of r dA = [h t rho + h^3 asinh(t / h)] / 6
// from t0 to t1, rho = sqrt(h^2 + t^2); an edge through p contributes 0. Exact whether p lies
// inside or outside the polygon.
struct DistanceIntegral {
  double area = 0.0;     // m^2
  double distance = 0.0; // m^3, integral of |x - p| dA
};
DistanceIntegral polygon_distance_integral(const Eigen::Vector3d *v, int n,
                                           const Eigen::Vector3d &p,
                                           const Eigen::Vector3d &normal);

} // namespace tri
