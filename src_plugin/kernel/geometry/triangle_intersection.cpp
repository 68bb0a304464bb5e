#include "geometry/triangle_intersection.h"

#include "geometry/distance_primitives.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace tri {

namespace {
geom::P3 to_p3(const Eigen::Vector3d &v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d to_eigen(const geom::P3 &p) { return {p.x, p.y, p.z}; }
} // namespace

SeparatingAxis min_overlap_axis(const Eigen::Vector3d a[3], const Eigen::Vector3d b[3]) {
  const Eigen::Vector3d ea[3] = {a[1] - a[0], a[2] - a[1], a[0] - a[2]};
  const Eigen::Vector3d eb[3] = {b[1] - b[0], b[2] - b[1], b[0] - b[2]};
  double l2 = 0.0;
  for (int k = 0; k < 3; ++k)
    l2 = std::max({l2, ea[k].squaredNorm(), eb[k].squaredNorm()});
  const double min_axis2 = geom::kSliverRatio * geom::kSliverRatio * l2 * l2;
  const Eigen::Vector3d centroid_step = (b[0] + b[1] + b[2] - a[0] - a[1] - a[2]) / 3.0;

  Eigen::Vector3d axes[11];
  axes[0] = ea[0].cross(a[2] - a[0]);
  axes[1] = eb[0].cross(b[2] - b[0]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      axes[2 + 3 * i + j] = ea[i].cross(eb[j]);

  SeparatingAxis best{Eigen::Vector3d::Zero(), INFINITY};
  for (const Eigen::Vector3d &axis : axes) {
    const double n2 = axis.squaredNorm();
    if (!(n2 > min_axis2))
      continue;
    const Eigen::Vector3d n = axis / std::sqrt(n2);
    double a_lo = INFINITY, a_hi = -INFINITY, b_lo = INFINITY, b_hi = -INFINITY;
    for (int k = 0; k < 3; ++k) {
      const double pa = n.dot(a[k]), pb = n.dot(b[k]);
      a_lo = std::min(a_lo, pa);
      a_hi = std::max(a_hi, pa);
      b_lo = std::min(b_lo, pb);
      b_hi = std::max(b_hi, pb);
    }
    const double move_plus = a_hi - b_lo;  // translate b along +n by this to separate
    const double move_minus = b_hi - a_lo; // translate b along -n by this to separate
    const bool plus =
        move_plus < move_minus || (move_plus == move_minus && n.dot(centroid_step) >= 0.0);
    const double depth = plus ? move_plus : move_minus;
    if (depth < best.depth)
      best = {plus ? n : Eigen::Vector3d(-n), depth};
  }
  if (best.depth == INFINITY) { // every axis degenerate: both triangles are collinear
    const double c2 = centroid_step.squaredNorm();
    best.normal = c2 > 0.0 ? Eigen::Vector3d(centroid_step / std::sqrt(c2))
                           : Eigen::Vector3d(Eigen::Vector3d::UnitX());
    best.depth = 0.0;
  }
  best.depth = std::max(0.0, best.depth);
  return best;
}

int edge_face_crossings(const Eigen::Vector3d a[3], const Eigen::Vector3d b[3],
                        Eigen::Vector3d points[6]) {
  using namespace geom;
  const P3 pa[3] = {to_p3(a[0]), to_p3(a[1]), to_p3(a[2])};
  const P3 pb[3] = {to_p3(b[0]), to_p3(b[1]), to_p3(b[2])};
  int count = 0;
  for (int side = 0; side < 2; ++side) {
    const P3 *edges = side == 0 ? pa : pb; // edges of this triangle ...
    const P3 *face = side == 0 ? pb : pa;  // ... against this face
    const Face f = face_of(face);
    for (int k = 0; k < 3; ++k) {
      P3 hit;
      if (edge_pierces_face(edges[k], edges[(k + 1) % 3], f, hit))
        points[count++] = to_eigen(hit);
    }
  }
  return count;
}

} // namespace tri
