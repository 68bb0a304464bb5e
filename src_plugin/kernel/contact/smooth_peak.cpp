#include "contact/smooth_peak.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace tri {

using Eigen::Matrix2d;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

// One facet's lift as a quadratic on the polygon's plane coordinates u:
// h(u) = c0 + g . u + u^T H u (from h = b^T K b, b = c + A u affine).
struct Lift {
  double c0 = 0.0;
  Vector2d g = Vector2d::Zero();
  Matrix2d H = Matrix2d::Zero();
  Vector2d gradient(const Vector2d &u) const { return g + 2.0 * H * u; }
};

} // namespace

SmoothPeak smooth_peak(const ContactPolygon &patch, const Vector3d a[3], const double *bulge_a,
                       const Vector3d b[3], const double *bulge_b, double shift) {
  SmoothPeak peak;
  const int n = patch.num_vertices;
  const Vector3d m = patch.direction;
  const Vector3d e1 = m.unitOrthogonal(), e2 = m.cross(e1);
  const Vector3d origin = n > 0 ? patch.vertices[0] : Vector3d::Zero();
  auto plane = [&](const Vector3d &x) {
    const Vector3d d = x - origin;
    return Vector2d(d.dot(e1), d.dot(e2));
  };
  // The polygon's overlap, affine: o(u) = o_0 + grad . u.
  const double o0 = n > 0 ? patch.corner_overlaps[0] - shift : 0.0;
  const Vector2d grad(patch.overlap_gradient.dot(e1), patch.overlap_gradient.dot(e2));
  auto lift_of = [&](const Vector3d t[3], const double *k) {
    Lift lift;
    if (!k)
      return lift;
    const Vector2d p0 = plane(t[0]);
    Matrix2d edges;
    edges.col(0) = plane(t[1]) - p0;
    edges.col(1) = plane(t[2]) - p0;
    const double det = edges.determinant();
    if (!(std::abs(det) > 0.0))
      return lift; // seen edge-on along m: not a polygon's facet
    const Matrix2d inv = edges.inverse();
    Eigen::Matrix<double, 3, 2> A;
    A.row(1) = inv.row(0);
    A.row(2) = inv.row(1);
    A.row(0) = -(A.row(1) + A.row(2));
    const Vector3d c = Vector3d(1.0, 0.0, 0.0) - A * p0;
    Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
    K(0, 1) = K(1, 0) = 0.5 * k[0];
    K(1, 2) = K(2, 1) = 0.5 * k[1];
    K(2, 0) = K(0, 2) = 0.5 * k[2];
    lift.c0 = c.dot(K * c);
    lift.g = 2.0 * A.transpose() * (K * c);
    lift.H = A.transpose() * K * A;
    return lift;
  };
  const Lift la = lift_of(a, bulge_a), lb = lift_of(b, bulge_b);
  const double c0 = o0 + la.c0 + lb.c0;
  const Vector2d g = grad + la.g + lb.g;
  const Matrix2d H = la.H + lb.H;
  auto value = [&](const Vector2d &u) { return c0 + g.dot(u) + u.dot(H * u); };

  double best = -std::numeric_limits<double>::infinity();
  Vector2d best_u = Vector2d::Zero();
  auto consider = [&](const Vector2d &u) {
    const double f = value(u);
    if (f > best) {
      best = f;
      best_u = u;
    }
  };
  const std::size_t count = static_cast<std::size_t>(n);
  Vector2d corners[kPolygonMaxVertices];
  double twice_area = 0.0;
  for (std::size_t k = 0; k < count; ++k)
    corners[k] = plane(patch.vertices[k]);
  for (std::size_t k = 0; k < count; ++k) {
    const Vector2d &p = corners[k], &q = corners[(k + 1) % count];
    twice_area += p.x() * q.y() - p.y() * q.x();
    consider(p);
    const Vector2d d = q - p;
    const double curve = d.dot(H * d);
    if (curve < 0.0) { // the quadratic along the edge has its top inside it, maybe
      const double t = -(g + 2.0 * H * p).dot(d) / (2.0 * curve);
      if (t > 0.0 && t < 1.0)
        consider(p + t * d);
    }
  }
  // The interior top of a concave quadratic, when it lies inside the polygon.
  if (H(0, 0) < 0.0 && H.determinant() > 0.0 && count >= 3) {
    const Vector2d top = -0.5 * H.inverse() * g;
    bool inside = true;
    for (std::size_t k = 0; k < count && inside; ++k) {
      const Vector2d &p = corners[k], &q = corners[(k + 1) % count];
      const Vector2d d = q - p, r = top - p;
      inside = (d.x() * r.y() - d.y() * r.x()) * twice_area >= 0.0;
    }
    if (inside)
      consider(top);
  }
  if (!(best > -std::numeric_limits<double>::infinity()))
    return peak;
  peak.overlap = best;
  // On the mid-surface between the two facets' planes (it contains the corners).
  const Vector3d mid = patch.normal_a + patch.normal_b;
  const Vector3d in_plane = best_u.x() * e1 + best_u.y() * e2;
  peak.point = origin + in_plane - (mid.dot(in_plane) / mid.dot(m)) * m;
  // Each smooth surface's normal towards +m: the facet's tilted by its lift's slope.
  const Vector2d ga = la.gradient(best_u), gb = lb.gradient(best_u);
  const double cos_a = patch.normal_a.dot(m), cos_b = patch.normal_b.dot(m);
  const Vector3d na = (patch.normal_a - (ga.x() * e1 + ga.y() * e2)) / cos_a;
  const Vector3d nb = (patch.normal_b + (gb.x() * e1 + gb.y() * e2)) / cos_b;
  const Vector3d sum = na + nb;
  const double len = sum.norm();
  peak.normal = std::isfinite(len) && len > 0.0 ? Vector3d(sum / len) : m;
  return peak;
}

} // namespace tri
