// Contact patch of two nearly parallel triangles; the design is in the header.
#include "contact_polygon.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tri {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

// Sutherland-Hodgman on a convex polygon adds at most one vertex per half-plane, but rounding
// can make nearly collinear vertices alternate sides; each clip at most doubles the count (a
// vertex and a crossing per edge), so a triangle clipped by 4 half-planes never exceeds 48.
constexpr int kClips = 4;
constexpr int kMaxVertices = 3 << kClips;

struct Polygon {
  Vector2d p[kMaxVertices];
  int n = 0;
};

double cross2(const Vector2d &a, const Vector2d &b) { return a.x() * b.y() - a.y() * b.x(); }

// The part of `in` where the affine function with values s[i] at its vertices is >= 0.
void clip(const Polygon &in, const double *s, Polygon &out) {
  out.n = 0;
  for (int i = 0; i < in.n; ++i) {
    const int j = i + 1 == in.n ? 0 : i + 1;
    const bool inside_i = s[i] >= 0.0, inside_j = s[j] >= 0.0;
    if (inside_i)
      out.p[out.n++] = in.p[i];
    if (inside_i != inside_j)
      out.p[out.n++] = in.p[i] + (s[i] / (s[i] - s[j])) * (in.p[j] - in.p[i]);
  }
}

// An affine function of the 2D coordinates: value0 + gradient . x.
struct Affine {
  double value0;
  Vector2d gradient;
  double operator()(const Vector2d &x) const { return value0 + gradient.dot(x); }
};

// Height along m of the plane through t0 with normal nt, at x (coordinates relative to origin
// o in the basis u, v); |nt . m| is bounded away from zero by the parallel test.
Affine plane_height(const Vector3d &nt, const Vector3d &t0, const Vector3d &o, const Vector3d &u,
                    const Vector3d &v, const Vector3d &m) {
  const double nm = nt.dot(m);
  return {nt.dot(t0 - o) / nm, Vector2d(-nt.dot(u) / nm, -nt.dot(v) / nm)};
}

} // namespace

bool contact_polygon(const Vector3d &a0, const Vector3d &a1, const Vector3d &a2, const Vector3d &b0,
                     const Vector3d &b1, const Vector3d &b2, const Vector3d &normal, double layer,
                     ContactPolygon &patch) {
  patch = ContactPolygon();
  const Vector3d ca = (a1 - a0).cross(a2 - a0), cb = (b1 - b0).cross(b2 - b0);
  const double la = ca.norm(), lb = cb.norm();
  if (!(la > 0.0) || !(lb > 0.0) || !std::isfinite(la + lb))
    return false;
  const Vector3d na = ca / la;
  Vector3d nb = cb / lb;
  const double c = na.dot(nb);
  if (std::abs(c) < std::cos(kParallelFaceAngle))
    return false;
  if (c < 0.0)
    nb = -nb;
  Vector3d m = (na + nb).normalized();
  if (m.dot(normal) < 0.0)
    m = -m;
  // Orthonormal basis (u, v, m), origin at a vertex of a: coordinates are relative, so the
  // result does not lose digits far from the world origin.
  int k = 0;
  m.cwiseAbs().minCoeff(&k);
  const Vector3d u = m.cross(Vector3d::Unit(k)).normalized();
  const Vector3d v = m.cross(u);
  const Vector3d &o = a0;
  auto project = [&](const Vector3d &x) { return Vector2d((x - o).dot(u), (x - o).dot(v)); };

  // Clip b's projection (counter-clockwise) by the three edges of a's (counter-clockwise).
  Vector2d pa[3] = {project(a0), project(a1), project(a2)};
  if (cross2(pa[1] - pa[0], pa[2] - pa[0]) < 0.0)
    std::swap(pa[1], pa[2]);
  Polygon poly[2];
  poly[0].n = 3;
  poly[0].p[0] = project(b0);
  poly[0].p[1] = project(b1);
  poly[0].p[2] = project(b2);
  if (cross2(poly[0].p[1] - poly[0].p[0], poly[0].p[2] - poly[0].p[0]) < 0.0)
    std::swap(poly[0].p[1], poly[0].p[2]);
  double s[kMaxVertices];
  int cur = 0;
  for (int e = 0; e < 3 && poly[cur].n > 0; ++e) {
    const Vector2d &p = pa[e], edge = pa[e == 2 ? 0 : e + 1] - p;
    for (int i = 0; i < poly[cur].n; ++i)
      s[i] = cross2(edge, poly[cur].p[i] - p);
    clip(poly[cur], s, poly[1 - cur]);
    cur = 1 - cur;
  }
  // Local overlap o = layer - (h_b - h_a), affine; keep o >= 0.
  const Affine ha = plane_height(na, a0, o, u, v, m), hb = plane_height(nb, b0, o, u, v, m);
  const Affine overlap{layer - (hb.value0 - ha.value0), -(hb.gradient - ha.gradient)};
  for (int i = 0; i < poly[cur].n; ++i)
    s[i] = overlap(poly[cur].p[i]);
  clip(poly[cur], s, poly[1 - cur]);
  const Polygon &q = poly[1 - cur];
  patch.min_triangle_area = 0.5 * std::min(la, lb);
  if (q.n < 3)
    return true;

  // Integrals over a fan from q.p[0]; for a linear f on a triangle of area A with vertex values
  // f_i at d_i: integral f dA = A (f_0 + f_1 + f_2) / 3 and integral f d dA =
  // A / 12 (sum_i f_i * sum_i d_i + sum_i f_i d_i). Coordinates relative to q.p[0].
  const Vector2d &p0 = q.p[0];
  const double o0 = std::max(0.0, overlap(p0));
  // Second moment of area about q.p[0]: integral of x x^T dA over the triangle (0, d1, d2) is
  // A/12 (d1 d1^T + d2 d2^T + (d1 + d2)(d1 + d2)^T).
  double area = 0.0, weight = 0.0;
  Vector2d moment = Vector2d::Zero(), area_moment = Vector2d::Zero();
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  for (int i = 1; i + 1 < q.n; ++i) {
    const Vector2d d1 = q.p[i] - p0, d2 = q.p[i + 1] - p0;
    const double o1 = std::max(0.0, overlap(q.p[i])), o2 = std::max(0.0, overlap(q.p[i + 1]));
    const double at = 0.5 * cross2(d1, d2);
    area += at;
    area_moment += at / 3.0 * (d1 + d2);
    weight += at * (o0 + o1 + o2) / 3.0;
    moment += at / 12.0 * ((o0 + o1 + o2) * (d1 + d2) + o1 * d1 + o2 * d2);
    const Vector2d d12 = d1 + d2;
    second += at / 12.0 * (d1 * d1.transpose() + d2 * d2.transpose() + d12 * d12.transpose());
  }
  if (!(area > 0.0))
    return true;
  patch.area = area;
  patch.weight = std::max(0.0, weight);
  const Vector2d cen = area_moment / area; // area centroid relative to p0
  const Vector2d c2 = p0 + (weight > 0.0 ? Vector2d(moment / weight) : cen);
  patch.centroid = o + c2.x() * u + c2.y() * v + 0.5 * (ha(c2) + hb(c2)) * m;
  const Vector2d ac2 = p0 + cen;
  patch.area_centroid = o + ac2.x() * u + ac2.y() * v + 0.5 * (ha(ac2) + hb(ac2)) * m;
  // Parallel-axis theorem to the centroid, then into the world frame: J = B J2 B^T, B = [u v].
  Eigen::Matrix2d j2 = second - area * cen * cen.transpose();
  j2(0, 1) = j2(1, 0) = 0.5 * (j2(0, 1) + j2(1, 0));
  Eigen::Matrix<double, 3, 2> basis;
  basis.col(0) = u;
  basis.col(1) = v;
  patch.second_moment = basis * j2 * basis.transpose();
  return true;
}

} // namespace tri
