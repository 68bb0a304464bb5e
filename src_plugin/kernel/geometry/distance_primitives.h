// Branch-free building blocks of the brute-force triangle distance (paper section 2: the
// 6 point-face and 9 edge-edge checks). Each function is written with selects instead of
// if-statements so that the same source serves the scalar reference (triangle_distance.cpp)
// and the loop vectorised across triangle pairs (brute_force_block): both evaluate the
// same operations in the same order and return bit-identical results.
//
// Units: any consistent length unit; every threshold below is relative to the input's own
// size, so results do not depend on the scale (tested from 1e-6 to 1e3).
#pragma once

#include <algorithm>
#include <cmath>

// Everything here is inlined into the vectorised loops: a call inside an `omp simd` loop
// stops GCC from vectorising it, and so do loops it has not fully unrolled.
#define TRI_INLINE inline __attribute__((always_inline))

namespace tri {
namespace geom {

struct P3 {
  double x, y, z;
};
TRI_INLINE P3 operator+(P3 a, P3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
TRI_INLINE P3 operator-(P3 a, P3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
TRI_INLINE P3 operator*(double s, P3 a) { return {s * a.x, s * a.y, s * a.z}; }
TRI_INLINE double dot(P3 a, P3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
TRI_INLINE P3 cross(P3 a, P3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
TRI_INLINE double clamp01(double v) { return std::min(1.0, std::max(0.0, v)); }
TRI_INLINE P3 select(bool c, P3 a, P3 b) { return {c ? a.x : b.x, c ? a.y : b.y, c ? a.z : b.z}; }

// A face whose doubled area |n| is below kSliverRatio * (longest edge)^2 is a sliver: its
// point-face checks are skipped and it is represented by its three edges only. The cut
// balances two errors, both <= kSliverRatio * longest edge: the face's width, ignored when
// skipping, and the rounding of its normal, which grows as 1/|n| when not skipping.
constexpr double kSliverRatio = 1e-8;

// Segments are parallel for the edge-edge solve when sin^2 of their angle is below this;
// the solve then picks the foot of one end point, off the closest pair by at most
// sin * length (1e-15 of the edge here). Above it the joint solve keeps that accuracy too,
// since it uses the cross product (segment_segment_dist2).
constexpr double kParallelSin2 = 1e-30;

// Squared lengths below this are zero-length edges (coincident vertices). Only to keep
// 1/|e|^2 finite; any nonzero edge at the supported scales is far above it.
constexpr double kTinySquared = 1e-200;

// Result of one check: squared distance and the closest point on each side.
struct CheckResult {
  double dist2;
  P3 pa, pb;
};

// A triangle prepared for the checks: corner v0, edges e1 = v1 - v0, e2 = v2 - v0, the
// (unnormalised) normal n = e1 x e2, its longest squared edge l2, whether it is not a
// sliver, and the in-plane edge normals m1 = n x e1 (edge v0 v1), m2 = e2 x n (edge v2 v0),
// m3 = n x (e2 - e1) (edge v1 v2), each pointing inwards: a point of the plane is in the
// closed triangle iff m1.(p - v0), m2.(p - v0), m3.(p - v1) are all >= 0. Every function
// below takes faces made by face_of, so all agree on what a sliver is.
//
// Accuracy on slivers (why n and the inside test are computed this way): the plain cross
// product e1 x e2 is rounded by ~1e-16 |e1| |e2| in every direction, a tilt of ~1e-16 l2 / |n|
// of the normal, which moved the foot of a point above a sliver of height 1e-7 of its length
// by ~1e-9 of that length (measured: 3e-10 at height 1e-7, 1.2e-9 at 2e-8;
// test_triangle_distance_slivers.cpp). Crossing e1 with the part of e2 normal to it instead
// rounds only by ~1e-16 |n| (the subtraction's own rounding tilts n about e1, by which the
// height of a point of the triangle changes by ~1e-16 |e2|), so the normal's direction is
// good to ~1e-16 whatever the shape. Likewise u + v <= 1 from barycentric weights about v0
// misplaced the edge v1 v2 by ~1e-16 l2 / |v2 - v1| when that edge is short; the edge tests
// about each edge's own end point misplace an edge by ~1e-16 of the distance to it only.
struct Face {
  P3 v0, e1, e2, n, m1, m2, m3;
  double l2;
  bool ok;
};
TRI_INLINE Face face_of(const P3 v[3]) {
  Face f;
  f.v0 = v[0];
  f.e1 = v[1] - v[0];
  f.e2 = v[2] - v[0];
  const P3 e3 = v[2] - v[1];
  const double a = dot(f.e1, f.e1);
  const double mu = a > kTinySquared ? dot(f.e1, f.e2) / a : 0.0;
  f.n = cross(f.e1, f.e2 - mu * f.e1); // = e1 x e2 in exact arithmetic, for any mu
  f.l2 = std::max(a, std::max(dot(f.e2, f.e2), dot(e3, e3)));
  f.ok = dot(f.n, f.n) > kSliverRatio * kSliverRatio * f.l2 * f.l2;
  f.m1 = cross(f.n, f.e1);
  f.m2 = cross(f.e2, f.n);
  f.m3 = cross(f.n, e3);
  return f;
}

// Is the point v0 + w of the plane of f in the closed triangle (edge tests of Face)?
TRI_INLINE bool in_face(const Face &f, P3 w) {
  return (dot(f.m1, w) >= 0.0) & (dot(f.m2, w) >= 0.0) & (dot(f.m3, w - f.e1) >= 0.0);
}

// Closest point of the plane of face f to p, valid when its foot lies in the closed triangle
// and the triangle is not a sliver; dist2 is +inf otherwise.
TRI_INLINE double point_face_dist2(P3 p, const Face &f, P3 &foot) {
  const double nn = dot(f.n, f.n);
  const double inv_nn = f.ok ? 1.0 / nn : 0.0;
  const P3 w = p - f.v0;
  const double h = dot(w, f.n) * inv_nn; // signed height in units of |n|
  foot = p - h * f.n;
  const bool inside = f.ok & in_face(f, w);
  const double d2 = h * h * nn;
  return inside ? d2 : INFINITY;
}

// Closest points of segments p1 + s d1 and p2 + t d2, s, t in [0, 1] (the classic clamped
// solve: unconstrained optimum, clamp t, re-solve s). Zero-length segments are points.
TRI_INLINE double segment_segment_dist2(P3 p1, P3 d1, P3 p2, P3 d2, P3 &c1, P3 &c2) {
  const P3 r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), b = dot(d1, d2);
  const double c = dot(d1, r), f = dot(d2, r);
  const double inv_a = a > kTinySquared ? 1.0 / a : 0.0;
  const double inv_e = e > kTinySquared ? 1.0 / e : 0.0;
  // Joint optimum s = (b f - c e) / (a e - b^2), both written through n = d1 x d2 (Lagrange's
  // identity): the differences of products lose all digits for nearly parallel edges
  // (relative error ~ 1e-16 / sin^2, a distance error up to 1e-7 of the edge, found by
  // tests/fuzz), the cross products only ~ 1e-16 / sin, which moves s along a direction in
  // which the distance changes by at most ~ 1e-16 of the edge.
  const P3 n = cross(d1, d2);
  const double denom = dot(n, n);
  const bool skew = denom > kParallelSin2 * a * e;
  // Skew: joint optimum. Parallel (or a degenerate segment): the foot of p2 on segment 1.
  const double s0 = skew ? clamp01(dot(n, cross(d2, r)) / denom) : clamp01(-c * inv_a);
  const double t0 = (b * s0 + f) * inv_e;
  const double t = clamp01(t0);
  const double s_low = clamp01(-c * inv_a), s_high = clamp01((b - c) * inv_a);
  const double s = t0 < 0.0 ? s_low : (t0 > 1.0 ? s_high : s0);
  c1 = p1 + s * d1;
  c2 = p2 + t * d2;
  const P3 g = c1 - c2;
  return dot(g, g);
}

// The 15 checks of one triangle pair. `a` and `b` hold the three vertices of each triangle.
// Returns the smallest squared distance and its closest points; ties keep the first check in
// the fixed order: vertices of a on face b, vertices of b on face a, then edge pairs (i, j).
TRI_INLINE CheckResult fifteen_checks(const P3 a[3], const P3 b[3], const Face &fa,
                                      const Face &fb) {
  const P3 ea[3] = {a[1] - a[0], a[2] - a[1], a[0] - a[2]};
  const P3 eb[3] = {b[1] - b[0], b[2] - b[1], b[0] - b[2]};
  CheckResult best{INFINITY, a[0], b[0]};
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k) {
    P3 foot;
    const double d2 = point_face_dist2(a[k], fb, foot);
    const bool better = d2 < best.dist2;
    best.dist2 = better ? d2 : best.dist2;
    best.pa = select(better, a[k], best.pa);
    best.pb = select(better, foot, best.pb);
  }
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k) {
    P3 foot;
    const double d2 = point_face_dist2(b[k], fa, foot);
    const bool better = d2 < best.dist2;
    best.dist2 = better ? d2 : best.dist2;
    best.pa = select(better, foot, best.pa);
    best.pb = select(better, b[k], best.pb);
  }
#pragma GCC unroll 3
  for (int i = 0; i < 3; ++i)
#pragma GCC unroll 3
    for (int j = 0; j < 3; ++j) {
      P3 c1, c2;
      const double d2 = segment_segment_dist2(a[i], ea[i], b[j], eb[j], c1, c2);
      const bool better = d2 < best.dist2;
      best.dist2 = better ? d2 : best.dist2;
      best.pa = select(better, c1, best.pa);
      best.pb = select(better, c2, best.pb);
    }
  return best;
}

// Does the edge p -> q cross the plane of face f strictly (end points on opposite sides) at
// a point of the closed triangle? This is the one way two triangles can intersect that the
// 15 checks do not see (they report the distance of the edges, not 0). Slivers are never
// pierced (their edges are checked). `hit` receives the crossing point.
TRI_INLINE bool edge_pierces_face(P3 p, P3 q, const Face &f, P3 &hit) {
  const double sp = dot(p - f.v0, f.n), sq = dot(q - f.v0, f.n);
  const bool crosses = ((sp > 0.0) & (sq < 0.0)) | ((sp < 0.0) & (sq > 0.0));
  const double t = crosses ? sp / (sp - sq) : 0.0;
  hit = p + t * (q - p);
  return crosses & f.ok & in_face(f, hit - f.v0);
}

} // namespace geom
} // namespace tri

namespace tri {
namespace geom {

// Does any edge of a pierce face b, or any edge of b pierce face a?
TRI_INLINE bool any_edge_pierces(const P3 a[3], const P3 b[3], const Face &fa, const Face &fb) {
  bool pierced = false;
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k) {
    P3 hit;
    pierced |= edge_pierces_face(a[k], a[(k + 1) % 3], fb, hit);
    pierced |= edge_pierces_face(b[k], b[(k + 1) % 3], fa, hit);
  }
  return pierced;
}

} // namespace geom
} // namespace tri
