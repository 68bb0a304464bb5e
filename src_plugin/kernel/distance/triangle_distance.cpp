#include "distance/triangle_distance.h"

#include "geometry/distance_primitives.h"
#include "geometry/triangle_intersection.h"

#include <cmath>

namespace tri {

using geom::P3;

namespace {

P3 to_p3(const Eigen::Vector3d &v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d to_eigen(const P3 &p) { return {p.x, p.y, p.z}; }

TRI_INLINE double touch_dist2(const geom::Face &fa, const geom::Face &fb) {
  return kTouchRatio * kTouchRatio * std::max(fa.l2, fb.l2);
}

// The result of a pair that the checks show separated: shared by the scalar and the block
// path so that both produce the same bits. The normal is normalised by its own length, not
// by the distance: far from the origin the difference of the points carries the rounding of
// their coordinates. If rounding leaves no difference at all, the minimum-overlap axis
// (triangle_intersection.h) stands in, so the normal is always finite.
TrianglePairDistance separated(const geom::CheckResult &best, const Eigen::Vector3d a[3],
                               const Eigen::Vector3d b[3]) {
  TrianglePairDistance r;
  r.distance = std::sqrt(best.dist2);
  r.point_a = to_eigen(best.pa);
  r.point_b = to_eigen(best.pb);
  const Eigen::Vector3d diff = r.point_b - r.point_a;
  const double length = diff.norm();
  r.normal = length > 0.0 ? Eigen::Vector3d(diff / length) : min_overlap_axis(a, b).normal;
  r.intersecting = false;
  r.penetration_depth = 0.0;
  r.lower_bound = r.distance;
  return r;
}

} // namespace

TrianglePairDistance triangle_distance(const Eigen::Vector3d a[3], const Eigen::Vector3d b[3]) {
  const P3 pa[3] = {to_p3(a[0]), to_p3(a[1]), to_p3(a[2])};
  const P3 pb[3] = {to_p3(b[0]), to_p3(b[1]), to_p3(b[2])};
  const geom::Face fa = geom::face_of(pa), fb = geom::face_of(pb);
  const geom::CheckResult best = geom::fifteen_checks(pa, pb, fa, fb);
  const bool touching = best.dist2 <= touch_dist2(fa, fb);
  Eigen::Vector3d crossings[6];
  const int ncross = edge_face_crossings(a, b, crossings);
  if (!touching && ncross == 0)
    return separated(best, a, b);

  TrianglePairDistance r;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < ncross; ++k)
    sum += crossings[k];
  int npoints = ncross;
  if (touching) {
    sum += 0.5 * (to_eigen(best.pa) + to_eigen(best.pb));
    ++npoints;
  }
  r.point_a = r.point_b = sum / npoints;
  r.distance = 0.0;
  r.intersecting = true;
  const SeparatingAxis axis = min_overlap_axis(a, b);
  r.normal = axis.normal;
  r.penetration_depth = axis.depth;
  return r;
}

namespace {

// The squared distance of triangle t from face f where a vertex of t over f is certainly the
// closest pair: every vertex of t strictly on one side of f's plane, and the one nearest the
// plane with its foot in f. No point of t is nearer the plane than that vertex (a triangle's
// extreme along a direction is a vertex), so no pair of points is nearer than its height, and
// the vertex and its foot attain it. -1 where that does not hold (or f is a sliver).
double vertex_over_face_dist2(const P3 t[3], const geom::Face &f) {
  double h[3];
  for (int k = 0; k < 3; ++k)
    h[k] = geom::dot(t[k] - f.v0, f.n);
  const bool above = h[0] > 0.0 && h[1] > 0.0 && h[2] > 0.0;
  const bool below = h[0] < 0.0 && h[1] < 0.0 && h[2] < 0.0;
  if (!(above || below))
    return -1.0;
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::fabs(h[i]) < std::fabs(h[k]))
      k = i;
  P3 foot;
  const double d2 = geom::point_face_dist2(t[k], f, foot); // inf: foot outside, or a sliver
  return std::isfinite(d2) ? d2 : -1.0;
}

} // namespace

double separated_triangle_distance(const Eigen::Vector3d a[3], const Eigen::Vector3d b[3]) {
  const P3 pa[3] = {to_p3(a[0]), to_p3(a[1]), to_p3(a[2])};
  const P3 pb[3] = {to_p3(b[0]), to_p3(b[1]), to_p3(b[2])};
  const geom::Face fa = geom::face_of(pa), fb = geom::face_of(pb);
  // Nearly parallel faces (the reduction's polygon members) mostly have a vertex over the
  // other face as their closest pair: certified, it is the distance without the 15 checks.
  double dist2 = vertex_over_face_dist2(pb, fa);
  if (dist2 < 0.0)
    dist2 = vertex_over_face_dist2(pa, fb);
  if (dist2 < 0.0)
    dist2 = geom::fifteen_checks(pa, pb, fa, fb).dist2;
  return dist2 <= touch_dist2(fa, fb) ? -1.0 : std::sqrt(dist2);
}

namespace {

// One lane of brute_force_block. A separate function so that its locals are not seen by the
// `omp simd` lowering of the caller (which would turn address-taken locals into per-lane
// arrays that GCC cannot vectorise); after inlining they are plain scalars again.
TRI_INLINE void brute_force_lane(const double (*c)[kPairLanes], int l, double *dist2,
                                 double (*pa)[kPairLanes], double (*pb)[kPairLanes], int *exact) {
  const P3 ta[3] = {
      {c[0][l], c[1][l], c[2][l]}, {c[3][l], c[4][l], c[5][l]}, {c[6][l], c[7][l], c[8][l]}};
  const P3 tb[3] = {{c[9][l], c[10][l], c[11][l]},
                    {c[12][l], c[13][l], c[14][l]},
                    {c[15][l], c[16][l], c[17][l]}};
  const geom::Face fa = geom::face_of(ta), fb = geom::face_of(tb);
  const geom::CheckResult best = geom::fifteen_checks(ta, tb, fa, fb);
  const bool touching = best.dist2 <= touch_dist2(fa, fb);
  exact[l] = touching | geom::any_edge_pierces(ta, tb, fa, fb);
  dist2[l] = best.dist2;
  pa[0][l] = best.pa.x, pa[1][l] = best.pa.y, pa[2][l] = best.pa.z;
  pb[0][l] = best.pb.x, pb[1][l] = best.pb.y, pb[2][l] = best.pb.z;
}

} // namespace

void brute_force_block(const TrianglePairBlock &block, int n, TrianglePairDistance out[]) {
  alignas(64) double dist2[kPairLanes], pa[3][kPairLanes], pb[3][kPairLanes];
  alignas(64) int exact[kPairLanes]; // touching or intersecting: finish with the scalar path
  // At most half the lanes used (the last fallbacks of a pair): half a block, same bits.
  if (n <= kPairLanes / 2) {
#pragma omp simd
    for (int l = 0; l < kPairLanes / 2; ++l)
      brute_force_lane(block.c, l, dist2, pa, pb, exact);
  } else {
#pragma omp simd
    for (int l = 0; l < kPairLanes; ++l)
      brute_force_lane(block.c, l, dist2, pa, pb, exact);
  }
  for (int l = 0; l < n; ++l) {
    if (exact[l]) {
      Eigen::Vector3d ta[3], tb[3];
      block.get_lane(l, ta, tb);
      out[l] = triangle_distance(ta, tb);
    } else {
      Eigen::Vector3d ta[3], tb[3];
      block.get_lane(l, ta, tb);
      out[l] = separated({dist2[l], {pa[0][l], pa[1][l], pa[2][l]}, {pb[0][l], pb[1][l], pb[2][l]}},
                         ta, tb);
    }
  }
}

} // namespace tri
