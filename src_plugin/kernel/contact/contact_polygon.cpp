// Contact patch of two nearly parallel triangles; the design is in the header.
#include "contact/contact_polygon.h"

#include "geometry/point_triangle.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <utility>

namespace tri {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

// kPolygonMaxVertices (header): a triangle clipped by kClips half-planes.
constexpr int kClips = 4;
constexpr int kMaxVertices = 3 << kClips;
static_assert(kMaxVertices == kPolygonMaxVertices, "the polygon bound of contact_polygon.h");

// Lines a polygon edge can lie on: b's edges 0..2, a's edges 3..5, the layer cut 6.
constexpr int kEdgeOfA = 3, kLayerCut = 6;

struct Polygon {
  Vector2d p[kMaxVertices];
  int line[kMaxVertices]; // the line of the edge from p[i] to p[i + 1]
  int n = 0;
};

double cross2(const Vector2d &a, const Vector2d &b) { return a.x() * b.y() - a.y() * b.x(); }

// The part of `in` where the affine function with values s[i] at its vertices is >= 0; its
// new edges lie on the line `label`.
void clip(const Polygon &in, const double *s, int label, Polygon &out) {
  out.n = 0;
  for (int i = 0; i < in.n; ++i) {
    const int j = i + 1 == in.n ? 0 : i + 1;
    const bool inside_i = s[i] >= 0.0, inside_j = s[j] >= 0.0;
    if (inside_i) {
      out.line[out.n] = in.line[i];
      out.p[out.n++] = in.p[i];
    }
    if (inside_i != inside_j) {
      out.line[out.n] = inside_i ? label : in.line[i];
      out.p[out.n++] = in.p[i] + (s[i] / (s[i] - s[j])) * (in.p[j] - in.p[i]);
    }
  }
}

// Closest points of the segments p0 p1 and q0 q1 (Ericson, Real-Time Collision Detection,
// 5.1.9), degenerate segments included.
void segment_closest(const Vector3d &p0, const Vector3d &p1, const Vector3d &q0,
                     const Vector3d &q1, Vector3d &cp, Vector3d &cq) {
  const Vector3d d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  double s = 0.0, t = 0.0;
  if (a <= 0.0 && e <= 0.0) {
    cp = p0;
    cq = q0;
    return;
  }
  if (a <= 0.0) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(r);
    if (e <= 0.0) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  cp = p0 + s * d1;
  cq = q0 + t * d2;
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

// The two triangles' unit normals (nb turned to na's side), their bisector m and a basis
// (u, v) of the plane orthogonal to it.
struct PolygonFrame {
  const Vector3d &na, &nb, &m, &u, &v;
};

// x in the frame's plane coordinates relative to o.
Vector2d project(const Vector3d &x, const Vector3d &o, const PolygonFrame &f) {
  return Vector2d((x - o).dot(f.u), (x - o).dot(f.v));
}

// b's projection (counter-clockwise) clipped by the three edges of a's (counter-clockwise),
// keeping track of the line each polygon edge lies on.
struct TriangleOverlap {
  Polygon poly[2];
  int cur = 0;         // poly[cur]: the result so far
  Vector3d a[3], b[3]; // the triangles as given
  Vector3d A[3], B[3]; // their corners counter-clockwise: B[k] to B[k + 1] is b's edge k,
                       // A[e] to A[e + 1] a's edge kEdgeOfA + e
};

void clip_triangles(const Vector3d (&a)[3], const Vector3d (&b)[3], const Vector3d &o,
                    const PolygonFrame &f, TriangleOverlap &t) {
  Vector2d pa[3] = {project(a[0], o, f), project(a[1], o, f), project(a[2], o, f)};
  for (int k = 0; k < 3; ++k) {
    t.a[k] = t.A[k] = a[k];
    t.b[k] = t.B[k] = b[k];
  }
  if (cross2(pa[1] - pa[0], pa[2] - pa[0]) < 0.0) {
    std::swap(pa[1], pa[2]);
    std::swap(t.A[1], t.A[2]);
  }
  Polygon &first = t.poly[0];
  first.n = 3;
  for (int k = 0; k < 3; ++k)
    first.p[k] = project(b[k], o, f);
  if (cross2(first.p[1] - first.p[0], first.p[2] - first.p[0]) < 0.0) {
    std::swap(first.p[1], first.p[2]);
    std::swap(t.B[1], t.B[2]);
  }
  for (int k = 0; k < 3; ++k)
    first.line[k] = k;
  double s[kMaxVertices];
  t.cur = 0;
  for (int e = 0; e < 3 && t.poly[t.cur].n > 0; ++e) {
    const Vector2d &p = pa[e], edge = pa[e == 2 ? 0 : e + 1] - p;
    for (int i = 0; i < t.poly[t.cur].n; ++i)
      s[i] = cross2(edge, t.poly[t.cur].p[i] - p);
    clip(t.poly[t.cur], s, kEdgeOfA + e, t.poly[1 - t.cur]);
    t.cur = 1 - t.cur;
  }
}

// Integrals over the polygon q, by a fan from q.p[0], of the overlap o (clamped at 0 per
// corner); positions relative to q.p[0].
struct FanIntegrals {
  double area = 0.0, weight = 0.0, weight2 = 0.0; // of 1, o, o^2
  Vector2d moment = Vector2d::Zero(), area_moment = Vector2d::Zero(); // of o x, of x
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();                  // of x x^T
};

// For a linear f on a triangle of area A with vertex values f_i at d_i: integral f dA =
// A (f_0 + f_1 + f_2) / 3 and integral f d dA = A / 12 (sum_i f_i * sum_i d_i + sum_i f_i d_i);
// integral of x x^T dA over the triangle (0, d1, d2) is A/12 (d1 d1^T + d2 d2^T + (d1 + d2)
// (d1 + d2)^T).
FanIntegrals integrate_fan(const Polygon &q, const Affine &overlap) {
  FanIntegrals r;
  const Vector2d &p0 = q.p[0];
  const double o0 = std::max(0.0, overlap(p0));
  for (int i = 1; i + 1 < q.n; ++i) {
    const Vector2d d1 = q.p[i] - p0, d2 = q.p[i + 1] - p0;
    const double o1 = std::max(0.0, overlap(q.p[i])), o2 = std::max(0.0, overlap(q.p[i + 1]));
    const double at = 0.5 * cross2(d1, d2);
    r.area += at;
    r.area_moment += at / 3.0 * (d1 + d2);
    r.weight += at * (o0 + o1 + o2) / 3.0;
    r.weight2 += at / 6.0 * (o0 * o0 + o1 * o1 + o2 * o2 + o0 * o1 + o1 * o2 + o2 * o0);
    r.moment += at / 12.0 * ((o0 + o1 + o2) * (d1 + d2) + o1 * d1 + o2 * d2);
    const Vector2d d12 = d1 + d2;
    r.second += at / 12.0 * (d1 * d1.transpose() + d2 * d2.transpose() + d12 * d12.transpose());
  }
  return r;
}

// The planes of the two triangles as heights along m over the frame's plane, and the local
// overlap o = layer - (h_b - h_a) cos(phi / 2) between them (affine).
struct OverlapField {
  Affine ha, hb, overlap;
  double c_half; // cos(phi / 2), phi the angle between the triangles
};

// The patch's area, integrals, directions and centroids from the fan integrals of q.
void set_integrals(const Polygon &q, const FanIntegrals &in, const OverlapField &field,
                   const Vector3d &o, const PolygonFrame &f, ContactPolygon &patch) {
  const Vector2d &p0 = q.p[0];
  patch.area = in.area;
  patch.weight = std::max(0.0, in.weight);
  patch.weight2 = std::max(0.0, in.weight2);
  patch.direction = f.m;
  patch.cos_half_angle = field.c_half;
  patch.normal_b = f.nb.dot(f.m) < 0.0 ? Vector3d(-f.nb) : f.nb;
  patch.normal_a = f.na.dot(f.m) < 0.0 ? Vector3d(-f.na) : f.na;
  patch.overlap_gradient = field.overlap.gradient.x() * f.u + field.overlap.gradient.y() * f.v;
  const Vector2d cen = in.area_moment / in.area; // area centroid relative to p0
  const Vector2d c2 = p0 + (in.weight > 0.0 ? Vector2d(in.moment / in.weight) : cen);
  patch.centroid = o + c2.x() * f.u + c2.y() * f.v + 0.5 * (field.ha(c2) + field.hb(c2)) * f.m;
  const Vector2d ac2 = p0 + cen;
  patch.area_centroid =
      o + ac2.x() * f.u + ac2.y() * f.v + 0.5 * (field.ha(ac2) + field.hb(ac2)) * f.m;
  // Parallel-axis theorem to the centroid, then into the world frame: J = B J2 B^T, B = [u v].
  Eigen::Matrix2d j2 = in.second - in.area * cen * cen.transpose();
  j2(0, 1) = j2(1, 0) = 0.5 * (j2(0, 1) + j2(1, 0));
  Eigen::Matrix<double, 3, 2> basis;
  basis.col(0) = f.u;
  basis.col(1) = f.v;
  patch.second_moment = basis * j2 * basis.transpose();
}

// Each corner lies on two lines (the edges before and after it): two of b's edges, a vertex of
// b; two of a's, a vertex of a; one of each, an edge crossing. Its exact closest points on the
// two triangles (vertex to triangle, or edge to edge) give its contact point and exact
// overlap, as the distance kernel's closest points do (the midpoint along m lies beside that
// pair's line by gap tan(phi / 2) / 2, and the affine o misses an edge pair's distance).
void set_corners(const Polygon &q, const TriangleOverlap &t, const OverlapField &field,
                 const Vector3d &o, const PolygonFrame &f, ContactPolygon &patch) {
  const Vector3d(&A)[3] = t.A, (&B)[3] = t.B;
  const Vector3d(&a)[3] = t.a, (&b)[3] = t.b;
  for (int i = 0; i < q.n; ++i) {
    const Vector2d &x = q.p[i];
    const Vector3d base = o + x.x() * f.u + x.y() * f.v;
    patch.vertices[i] = base + 0.5 * (field.ha(x) + field.hb(x)) * f.m;
    patch.corner_overlaps[i] = std::max(0.0, field.overlap(x));
    patch.max_overlap = std::max(patch.max_overlap, patch.corner_overlaps[i]);
    const int in = q.line[i == 0 ? q.n - 1 : i - 1], out = q.line[i];
    Vector3d pa_c = patch.vertices[i], pb_c = patch.vertices[i];
    bool exact = true;
    if (in == kLayerCut || out == kLayerCut) {
      exact = false; // on the layer's edge: o = 0, no weight anywhere it is used
    } else if (in < kEdgeOfA && out < kEdgeOfA) { // b's vertex B[out] over a
      pb_c = B[out];
      pa_c = closest_point_on_triangle(pb_c, a[0], a[1], a[2]);
    } else if (in >= kEdgeOfA && out >= kEdgeOfA) { // a's vertex A[out - 3] over b
      pa_c = A[out - kEdgeOfA];
      pb_c = closest_point_on_triangle(pa_c, b[0], b[1], b[2]);
    } else {
      const int eb = in < kEdgeOfA ? in : out, ea = (in < kEdgeOfA ? out : in) - kEdgeOfA;
      segment_closest(A[ea], A[ea == 2 ? 0 : ea + 1], B[eb], B[eb == 2 ? 0 : eb + 1], pa_c,
                      pb_c);
    }
    patch.corner_points[i] = 0.5 * (pa_c + pb_c);
    patch.corner_distances[i] = exact ? (pb_c - pa_c).norm() : -1.0;
  }
}

} // namespace

bool contact_polygon(const Vector3d &a0, const Vector3d &a1, const Vector3d &a2, const Vector3d &b0,
                     const Vector3d &b1, const Vector3d &b2, const Vector3d &normal, double layer,
                     ContactPolygon &patch, double max_angle) {
  // The defaults of the fields, without copying the corner arrays (3 KB, meaningful only up to
  // num_vertices): an assignment from ContactPolygon() would copy them for every triangle pair.
  patch.~ContactPolygon();
  new (&patch) ContactPolygon;
  const Vector3d ca = (a1 - a0).cross(a2 - a0), cb = (b1 - b0).cross(b2 - b0);
  const double la = ca.norm(), lb = cb.norm();
  if (!(la > 0.0) || !(lb > 0.0) || !std::isfinite(la + lb))
    return false;
  const Vector3d na = ca / la;
  Vector3d nb = cb / lb;
  const double c = na.dot(nb);
  static const double parallel_cos = std::cos(kParallelFaceAngle);
  if (std::abs(c) < (max_angle == kParallelFaceAngle ? parallel_cos : std::cos(max_angle)))
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
  const PolygonFrame f{na, nb, m, u, v};
  TriangleOverlap t;
  clip_triangles({a0, a1, a2}, {b0, b1, b2}, o, f, t);
  // Keep o >= 0.
  OverlapField field;
  field.ha = plane_height(f.na, a0, o, f.u, f.v, f.m);
  field.hb = plane_height(f.nb, b0, o, f.u, f.v, f.m);
  field.c_half = std::abs(f.m.dot(f.na));
  field.overlap = {layer - field.c_half * (field.hb.value0 - field.ha.value0),
                   -field.c_half * (field.hb.gradient - field.ha.gradient)};
  double s[kMaxVertices];
  const Polygon &clipped = t.poly[t.cur];
  for (int i = 0; i < clipped.n; ++i)
    s[i] = field.overlap(clipped.p[i]);
  clip(clipped, s, kLayerCut, t.poly[1 - t.cur]);
  const Polygon &q = t.poly[1 - t.cur];
  patch.min_triangle_area = 0.5 * std::min(la, lb);
  if (q.n < 3)
    return true;
  const FanIntegrals integrals = integrate_fan(q, field.overlap);
  if (!(integrals.area > 0.0))
    return true;
  set_integrals(q, integrals, field, o, f, patch);
  patch.num_vertices = q.n;
  set_corners(q, t, field, o, f, patch);
  return true;
}

ExcessIntegral excess_over(const ContactPolygon &patch, double level, const Vector3d &origin) {
  ExcessIntegral r;
  const int n = patch.num_vertices;
  if (n < 3 || !(patch.max_overlap > level))
    return r;
  // Sutherland-Hodgman against o >= level on the corners (o is affine along the polygon).
  Vector3d x[2 * kPolygonMaxVertices]; // one clip adds at most a vertex per edge
  double e[2 * kPolygonMaxVertices];
  int k = 0;
  for (int i = 0; i < n; ++i) {
    const int j = i + 1 == n ? 0 : i + 1;
    const double si = patch.corner_overlaps[i] - level, sj = patch.corner_overlaps[j] - level;
    if (si >= 0.0) {
      x[k] = patch.vertices[i] - origin;
      e[k++] = si;
    }
    if ((si >= 0.0) != (sj >= 0.0)) {
      const double t = si / (si - sj);
      x[k] = patch.vertices[i] - origin + t * (patch.vertices[j] - patch.vertices[i]);
      e[k++] = 0.0;
    }
  }
  if (k < 3)
    return r;
  // Fan from x[0]; areas measured along the polygon's direction (as its area).
  const Vector3d &m = patch.direction;
  for (int i = 1; i + 1 < k; ++i) {
    const Vector3d d1 = x[i] - x[0], d2 = x[i + 1] - x[0];
    const double at = 0.5 * d1.cross(d2).dot(m);
    const double sum = e[0] + e[i] + e[i + 1];
    r.weight += at * sum / 3.0;
    r.moment += at / 12.0 * (sum * (x[0] + x[i] + x[i + 1]) + e[0] * x[0] + e[i] * x[i] +
                             e[i + 1] * x[i + 1]);
    // integral of e^2 over the triangle: at / 6 (sum of e_i^2 + sum of e_i e_j)
    r.square += at / 6.0 *
                (e[0] * e[0] + e[i] * e[i] + e[i + 1] * e[i + 1] + e[0] * e[i] + e[i] * e[i + 1] +
                 e[i + 1] * e[0]);
  }
  if (r.weight < 0.0) { // the corners ran clockwise about m
    r.weight = -r.weight;
    r.moment = -r.moment;
    r.square = -r.square;
  }
  return r;
}

void add_overlap_moments(const ContactPolygon &patch, double layer, const Vector3d &normal,
                         const Vector3d &origin, OverlapMoments &sum) {
  if (patch.num_vertices < 3 || !(patch.cos_half_angle > 0.0))
    return;
  // Fan from corner 0; each corner taken on a's surface (below the mid-surface by half the gap
  // along m), where o is layer minus the distance from b's plane whatever m is, so neighbouring
  // polygons of a's facets share their corners; projected onto the plane through `origin`
  // orthogonal to `normal`; areas signed by the corners' order (counter-clockwise about m), turned positive.
  // For a linear f on a triangle (barycentric l): integral f dA = A / 3 sum f_i, integral
  // f x dA = A / 12 (sum f_i sum x_i + sum f_i x_i); cubic terms from integral of l_i l_j l_k
  // dA = A / 60 (1 + d_ij + d_ik + d_jk + 2 d_ij d_jk) (Kronecker d): integral o^3 dA = A / 10
  // h3(o_0, o_1, o_2) (complete homogeneous symmetric polynomial), integral o^2 x dA = A / 60
  // sum_j x_j (S^2 + sum_i o_i^2 + 2 o_j S + 2 o_j^2), S = sum_i o_i.
  const double orientation = patch.direction.dot(normal) < 0.0 ? -1.0 : 1.0;
  auto flat = [&](int i) {
    const double gap = (layer - patch.corner_overlaps[i]) / patch.cos_half_angle;
    const Vector3d d = patch.vertices[i] - 0.5 * gap * patch.direction - origin;
    return Vector3d(d - d.dot(normal) * normal);
  };
  const Vector3d x0 = flat(0);
  const double o0 = patch.corner_overlaps[0];
  const double area0 = sum.area, m10 = sum.m1, m20 = sum.m2;
  for (int i = 1; i + 1 < patch.num_vertices; ++i) {
    const Vector3d x1 = flat(i), x2 = flat(i + 1);
    const double o1 = patch.corner_overlaps[i], o2 = patch.corner_overlaps[i + 1];
    const double at = 0.5 * orientation * (x1 - x0).cross(x2 - x0).dot(normal);
    const double s1 = o0 + o1 + o2, squares = o0 * o0 + o1 * o1 + o2 * o2;
    const double pairs = o0 * o1 + o1 * o2 + o2 * o0;
    sum.area += at;
    sum.area1 += at / 3.0 * (x0 + x1 + x2);
    sum.m1 += at / 3.0 * s1;
    sum.m2 += at / 6.0 * (squares + pairs);
    sum.m3 += at / 10.0 *
              (o0 * o0 * o0 + o1 * o1 * o1 + o2 * o2 * o2 + o0 * o0 * (o1 + o2) +
               o1 * o1 * (o0 + o2) + o2 * o2 * (o0 + o1) + o0 * o1 * o2);
    sum.first1 += at / 12.0 * (s1 * (x0 + x1 + x2) + o0 * x0 + o1 * x1 + o2 * x2);
    sum.second1 += at / 60.0 *
                   ((s1 * s1 + squares + 2.0 * o0 * s1 + 2.0 * o0 * o0) * x0 +
                    (s1 * s1 + squares + 2.0 * o1 * s1 + 2.0 * o1 * o1) * x1 +
                    (s1 * s1 + squares + 2.0 * o2 * s1 + 2.0 * o2 * o2) * x2);
  }
  sum.area_normal_a += (sum.area - area0) * patch.normal_a;
  sum.area_normal += (sum.area - area0) * patch.normal_b;
  sum.m1_normal += (sum.m1 - m10) * patch.normal_b;
  sum.m2_normal += (sum.m2 - m20) * patch.normal_b;
}

CurvedPeak curved_peak(double area, double m1, double m2, double m3) {
  CurvedPeak c;
  if (!(area > 0.0 && m1 > 0.0 && m2 > 0.0 && m3 > 0.0))
    return c;
  const double t = m1 * m3 / (m2 * m2);
  const double x = (1.35 - t) / 0.1;
  c.validity = !(x > 0.0) ? 0.0 : !(x < 1.0) ? 1.0 : x * x * (3.0 - 2.0 * x);
  if (!(c.validity > 0.0))
    return c;
  const double den = 3.0 * m2 * m2 - 2.0 * m1 * m3; // >= 0.3 m2^2 where valid
  c.peak = m2 * m3 / den;
  const double den2 = den * den;
  // Partial derivatives of the peak in M1, M2, M3, times dM_p / do(c_(p-1)) = p M_(p-1).
  c.a_area = 2.0 * m2 * m3 * m3 / den2 * area;
  c.a_pressure = -m3 * (3.0 * m2 * m2 + 2.0 * m1 * m3) / den2 * 2.0 * m1;
  c.a_second = 3.0 * m2 * m2 * m2 / den2 * 3.0 * m2;
  return c;
}

DistanceIntegral polygon_distance_integral(const Vector3d *vertices, int n, const Vector3d &p,
                                           const Vector3d &normal) {
  DistanceIntegral r;
  if (n < 3)
    return r;
  int k = 0;
  normal.cwiseAbs().minCoeff(&k);
  const Vector3d u = normal.cross(Vector3d::Unit(k)).normalized();
  const Vector3d v = normal.cross(u);
  auto project = [&](const Vector3d &x) { return Vector2d((x - p).dot(u), (x - p).dot(v)); };
  // Antiderivative along an edge's line at distance h: (h t rho + h^3 asinh(t / h)) / 6, taken
  // from ta to tb with one logarithm instead of two asinh: asinh(t / h) = log(g(t) / h) with
  // g(t) = t + rho, written h^2 / (rho - t) for t < 0 (no cancellation; (t + rho)(rho - t) = h^2).
  auto edge_part = [](double h, double ta, double tb) {
    const double h2 = h * h;
    const double ra = std::sqrt(h2 + ta * ta), rb = std::sqrt(h2 + tb * tb);
    const double ga = ta >= 0.0 ? ta + ra : h2 / (ra - ta);
    const double gb = tb >= 0.0 ? tb + rb : h2 / (rb - tb);
    return (h * (tb * rb - ta * ra) + h2 * h * std::log(gb / ga)) / 6.0;
  };
  double area = 0.0, distance = 0.0;
  Vector2d a = project(vertices[n - 1]);
  for (int i = 0; i < n; ++i) {
    const Vector2d b = project(vertices[i]);
    const double twice = cross2(a, b); // signed, twice the fan triangle's area
    area += 0.5 * twice;
    const Vector2d edge = b - a;
    const double length = edge.norm();
    if (length > 0.0 && twice != 0.0) {
      const Vector2d e = edge / length;
      const double h = std::abs(twice) / length;
      const double ta = a.dot(e), tb = b.dot(e); // positions from the foot of the perpendicular
      const double part = edge_part(h, ta, tb);
      distance += twice > 0.0 ? part : -part;
    }
    a = b;
  }
  r.area = std::abs(area);
  r.distance = area < 0.0 ? -distance : distance;
  return r;
}

} // namespace tri
