// Separating axes between two bodies of triangles: a cheap, exact proof that no triangle pair
// of the two is in contact, so a body pair that touches nothing costs O(vertices) instead of a
// triangle-pair search. The host keeps the last proven axis of each body
// pair (pair tri/gran in LIGGGHTS's contact history, fix tri/wall per atom and mesh) and hands
// it back the next step; body_interaction.h verifies it before anything else.
//
// Proof: for any direction n with |n| <= 1 the distance between two point sets is at least the
// gap between their projections on n, min_b n.q - max_a n.p. Triangles are convex hulls of
// their vertices, so the projections of the vertices bound those of the triangles. If that
// gap is at least the contact cutoff (eps_a + eps_b) plus a slack, every triangle pair is
// farther apart than the cutoff, and every distance kernel (brute force included) agrees.
//
// Rounding: the projections are computed in floating point from the same world-frame vertices
// the distance kernels read. Their error is below 4 u sqrt(3) M for vertices of magnitude up
// to M (u = 2^-53), and a brute-force distance is within a few u of the larger coordinate as
// well; the slack, kSeparationSlackRatio * (M_a + M_b + cutoff), is six orders of magnitude
// above both, and a pair inside it simply takes the full search. So an axis that passes never
// hides a pair that any kernel of distance_kernels.h would report within the cutoff. The same
// holds for extents from a pose (posed_extent): the world vertices the kernels would read are
// the rounded transform of the same body-frame vertices, a few u of |x| + radius away.
//
// Units: lengths in the unit of the triangles (metres in the simulation). Directions are
// world-frame; `axis` need not be normalised (it is, before use); a zero or non-finite axis
// proves nothing.
#pragma once

#include "geometry/triangle_soa.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tri {

constexpr double kSeparationSlackRatio = 1e-9;

// Extent of a body's vertices along a unit direction, and the largest |coordinate| among them.
// Empty body: lo = +inf, hi = -inf, magnitude 0.
struct Extent {
  double lo, hi, magnitude;
};
Extent soa_extent(const TriangleSoA &t, const Eigen::Vector3d &unit_axis);

// The same extent for a rigid body whose world-frame vertices are not built: body-frame
// vertices `frame` placed at x with orientation q (body frame -> world), projected as
// (q^-1 n) . p + n . x. Equal to soa_extent of the transformed vertices up to rounding (a few
// u times |x| + radius), far inside the slack; the magnitude is |x|_max + radius (`radius`: the
// farthest vertex from x), a bound on every world coordinate. A host can thus verify a kept
// axis of a pair that touches nothing without building either body's world triangles.
Extent posed_extent(const TriangleSoA &frame, const Eigen::Quaterniond &q,
                    const Eigen::Vector3d &x, double radius, const Eigen::Vector3d &unit_axis);

// The gap proven along `axis` between a (behind) and b (ahead): min_b - max_a minus the slack;
// -inf for an unusable axis or an empty body. Separated for a cutoff c when the result >= c.
double proven_gap(const TriangleSoA &a, const TriangleSoA &b, const Eigen::Vector3d &axis,
                  double cutoff);
// The same from the two bodies' extents along the (unit) axis.
double proven_gap(const Extent &a, const Extent &b, double cutoff);

// True when `axis` (pointing from a towards b) proves every triangle pair of a and b at least
// `cutoff` apart; `gap`, if given, receives the proven gap (for a cache that keeps it).
inline bool separated_along(const TriangleSoA &a, const TriangleSoA &b, const Eigen::Vector3d &axis,
                            double cutoff, double *gap = nullptr) {
  const double g = proven_gap(a, b, axis, cutoff);
  if (gap)
    *gap = g;
  return g >= cutoff;
}

} // namespace tri
