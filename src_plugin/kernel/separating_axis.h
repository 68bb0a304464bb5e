// Separating axes between two bodies of triangles: a cheap, exact proof that no triangle pair
// of the two is in contact, so a body pair that touches nothing costs O(vertices) instead of a
// triangle-pair search (issue 12, item 2). The host keeps the last proven axis of each body
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
// hides a pair that any kernel of distance_kernels.h would report within the cutoff.
//
// Units: lengths in the unit of the triangles (metres in the simulation). Directions are
// world-frame; `axis` need not be normalised (it is, before use); a zero or non-finite axis
// proves nothing.
#pragma once

#include "triangle_soa.h"

#include <Eigen/Core>

namespace tri {

constexpr double kSeparationSlackRatio = 1e-9;

// Extent of a body's vertices along a unit direction, and the largest |coordinate| among them.
// Empty body: lo = +inf, hi = -inf, magnitude 0.
struct Extent {
  double lo, hi, magnitude;
};
Extent soa_extent(const TriangleSoA &t, const Eigen::Vector3d &unit_axis);

// The gap proven along `axis` between a (behind) and b (ahead): min_b - max_a minus the slack;
// -inf for an unusable axis or an empty body. Separated for a cutoff c when the result >= c.
double proven_gap(const TriangleSoA &a, const TriangleSoA &b, const Eigen::Vector3d &axis,
                  double cutoff);

// True when `axis` (pointing from a towards b) proves every triangle pair of a and b at least
// `cutoff` apart.
inline bool separated_along(const TriangleSoA &a, const TriangleSoA &b, const Eigen::Vector3d &axis,
                            double cutoff) {
  return proven_gap(a, b, axis, cutoff) >= cutoff;
}

} // namespace tri
