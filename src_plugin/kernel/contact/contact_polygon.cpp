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

} // namespace

bool contact_polygon(const Vector3d &a0, const Vector3d &a1, const Vector3d &a2, const Vector3d &b0,
                     const Vector3d &b1, const Vector3d &b2, const Vector3d &normal, double layer,
                     ContactPolygon &patch, double max_angle) {
  // The defaults of the fields, without copying the corner arrays (3 KB, meaningful only up to
  // num_vertices): an assignment from ContactPolygon() copied them for every triangle pair.
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
  auto project = [&](const Vector3d &x) { return Vector2d((x - o).dot(u), (x - o).dot(v)); };

  // Clip b's projection (counter-clockwise) by the three edges of a's (counter-clockwise),
  // keeping track of the line each polygon edge lies on (corner_points below).
  Vector3d B[3] = {b0, b1, b2};
  Vector3d Ao[3] = {a0, a1, a2};
  Vector2d pa[3] = {project(a0), project(a1), project(a2)};
  if (cross2(pa[1] - pa[0], pa[2] - pa[0]) < 0.0) {
    std::swap(pa[1], pa[2]);
    std::swap(Ao[1], Ao[2]);
  }
  Polygon poly[2];
  poly[0].n = 3;
  poly[0].p[0] = project(b0);
  poly[0].p[1] = project(b1);
  poly[0].p[2] = project(b2);
  if (cross2(poly[0].p[1] - poly[0].p[0], poly[0].p[2] - poly[0].p[0]) < 0.0) {
    std::swap(poly[0].p[1], poly[0].p[2]);
    std::swap(B[1], B[2]);
  }
  for (int k = 0; k < 3; ++k)
    poly[0].line[k] = k; // b's edge from B[k] to B[k + 1]
  double s[kMaxVertices];
  int cur = 0;
  for (int e = 0; e < 3 && poly[cur].n > 0; ++e) {
    const Vector2d &p = pa[e], edge = pa[e == 2 ? 0 : e + 1] - p;
    for (int i = 0; i < poly[cur].n; ++i)
      s[i] = cross2(edge, poly[cur].p[i] - p);
    clip(poly[cur], s, kEdgeOfA + e, poly[1 - cur]); // a's edge from Ao[e] to Ao[e + 1]
    cur = 1 - cur;
  }
  // Local overlap o = layer - (h_b - h_a) cos(phi / 2), affine; keep o >= 0.
  const Affine ha = plane_height(na, a0, o, u, v, m), hb = plane_height(nb, b0, o, u, v, m);
  const double c_half = std::abs(m.dot(na)); // cos(phi / 2), phi the angle between them
  const Affine overlap{layer - c_half * (hb.value0 - ha.value0),
                       -c_half * (hb.gradient - ha.gradient)};
  for (int i = 0; i < poly[cur].n; ++i)
    s[i] = overlap(poly[cur].p[i]);
  clip(poly[cur], s, kLayerCut, poly[1 - cur]);
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
  double area = 0.0, weight = 0.0, weight2 = 0.0;
  Vector2d moment = Vector2d::Zero(), area_moment = Vector2d::Zero();
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  for (int i = 1; i + 1 < q.n; ++i) {
    const Vector2d d1 = q.p[i] - p0, d2 = q.p[i + 1] - p0;
    const double o1 = std::max(0.0, overlap(q.p[i])), o2 = std::max(0.0, overlap(q.p[i + 1]));
    const double at = 0.5 * cross2(d1, d2);
    area += at;
    area_moment += at / 3.0 * (d1 + d2);
    weight += at * (o0 + o1 + o2) / 3.0;
    weight2 += at / 6.0 * (o0 * o0 + o1 * o1 + o2 * o2 + o0 * o1 + o1 * o2 + o2 * o0);
    moment += at / 12.0 * ((o0 + o1 + o2) * (d1 + d2) + o1 * d1 + o2 * d2);
    const Vector2d d12 = d1 + d2;
    second += at / 12.0 * (d1 * d1.transpose() + d2 * d2.transpose() + d12 * d12.transpose());
  }
  if (!(area > 0.0))
    return true;
  patch.area = area;
  patch.weight = std::max(0.0, weight);
  patch.weight2 = std::max(0.0, weight2);
  patch.direction = m;
  patch.cos_half_angle = c_half;
  patch.normal_b = nb.dot(m) < 0.0 ? Vector3d(-nb) : nb;
  patch.normal_a = na.dot(m) < 0.0 ? Vector3d(-na) : na;
  patch.overlap_gradient = overlap.gradient.x() * u + overlap.gradient.y() * v;
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
  patch.num_vertices = q.n;
  // Each corner lies on two lines (the edges before and after it): two of b's edges, a vertex
  // of b; two of a's, a vertex of a; one of each, an edge crossing. Its exact closest points on
  // the two triangles (vertex to triangle, or edge to edge) give its contact point and exact
  // overlap, as the distance kernel's closest points do (the midpoint along m lies beside that
  // pair's line by gap tan(phi / 2) / 2, and the affine o misses an edge pair's distance).
  for (int i = 0; i < q.n; ++i) {
    const Vector2d &x = q.p[i];
    const Vector3d base = o + x.x() * u + x.y() * v;
    patch.vertices[i] = base + 0.5 * (ha(x) + hb(x)) * m;
    patch.corner_overlaps[i] = std::max(0.0, overlap(x));
    patch.max_overlap = std::max(patch.max_overlap, patch.corner_overlaps[i]);
    const int in = q.line[i == 0 ? q.n - 1 : i - 1], out = q.line[i];
    Vector3d pa_c = patch.vertices[i], pb_c = patch.vertices[i];
    bool exact = true;
    if (in == kLayerCut || out == kLayerCut) {
      exact = false; // on the layer's edge: o = 0, no weight anywhere it is used
    } else if (in < kEdgeOfA && out < kEdgeOfA) { // b's vertex B[out] over a
      pb_c = B[out];
      pa_c = closest_point_on_triangle(pb_c, a0, a1, a2);
    } else if (in >= kEdgeOfA && out >= kEdgeOfA) { // a's vertex Ao[out - 3] over b
      pa_c = Ao[out - kEdgeOfA];
      pb_c = closest_point_on_triangle(pa_c, b0, b1, b2);
    } else {
      const int eb = in < kEdgeOfA ? in : out, ea = (in < kEdgeOfA ? out : in) - kEdgeOfA;
      segment_closest(Ao[ea], Ao[ea == 2 ? 0 : ea + 1], B[eb], B[eb == 2 ? 0 : eb + 1], pa_c,
                      pb_c);
    }
    patch.corner_points[i] = 0.5 * (pa_c + pb_c);
    patch.corner_distances[i] = exact ? (pb_c - pa_c).norm() : -1.0;
  }
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
