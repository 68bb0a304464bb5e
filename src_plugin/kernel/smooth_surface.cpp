#include "smooth_surface.h"

#include <algorithm>
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <limits>

namespace tri {

namespace {

using Eigen::Matrix2d;
using Eigen::Vector2d;
using Eigen::Vector3d;

double smoothstep01(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

double angle_between(const Vector3d &u, const Vector3d &v) {
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// One facet's lift as a quadratic on the polygon's plane coordinates u:
// h(u) = c0 + g . u + u^T H u (from h = b^T K b, b = c + A u affine).
struct Lift {
  double c0 = 0.0;
  Vector2d g = Vector2d::Zero();
  Matrix2d H = Matrix2d::Zero();
  Vector2d gradient(const Vector2d &u) const { return g + 2.0 * H * u; }
};

// The normal of the quadric height field through vertex v and its neighbours `ring`, over the
// plane orthogonal to `guess` (unit); `guess` itself where the fit is not determined (fewer
// than 5 neighbours, or neighbours on a line).
Vector3d fitted_normal(const TriangleMesh &mesh, int v, const std::vector<int> &ring,
                       const Vector3d &guess) {
  if (guess.isZero() || ring.size() < 5)
    return guess;
  const Vector3d t1 = guess.unitOrthogonal(), t2 = guess.cross(t1);
  const Vector3d p = mesh.vertices[v];
  Eigen::Matrix<double, Eigen::Dynamic, 5> A(ring.size(), 5);
  Eigen::VectorXd z(ring.size());
  double scale = 0.0;
  for (int q : ring)
    scale = std::max(scale, (mesh.vertices[q] - p).norm());
  if (!(scale > 0.0))
    return guess;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vector3d d = (mesh.vertices[ring[i]] - p) / scale;
    const double x = d.dot(t1), y = d.dot(t2);
    A.row(i) << x, y, x * x, x * y, y * y;
    z(i) = d.dot(guess);
  }
  const Eigen::ColPivHouseholderQR<Eigen::Matrix<double, Eigen::Dynamic, 5>> qr(A);
  if (qr.rank() < 5)
    return guess;
  const Eigen::Matrix<double, 5, 1> c = qr.solve(z);
  const Vector3d n = guess - c(0) * t1 - c(1) * t2;
  return std::isfinite(n.norm()) ? Vector3d(n.normalized()) : guess;
}

} // namespace

std::vector<double> edge_bulges(const TriangleMesh &mesh) {
  const int nt = mesh.num_triangles();
  const std::size_t nv = mesh.vertices.size();
  std::vector<Vector3d> face(nt, Vector3d::Zero()), normal(nv, Vector3d::Zero());
  for (int t = 0; t < nt; ++t) {
    const Vector3d n = (mesh.corner(t, 1) - mesh.corner(t, 0))
                           .cross(mesh.corner(t, 2) - mesh.corner(t, 0));
    const double len = n.norm();
    if (!(len > 0.0))
      continue; // a sliver of zero area has no normal and votes for none
    face[t] = n / len;
    for (int k = 0; k < 3; ++k) {
      const Vector3d p = mesh.corner(t, k);
      const double angle =
          angle_between(mesh.corner(t, (k + 1) % 3) - p, mesh.corner(t, (k + 2) % 3) - p);
      normal[mesh.triangles[t][k]] += angle * face[t];
    }
  }
  for (Vector3d &n : normal) {
    const double len = n.norm();
    n = len > 0.0 ? Vector3d(n / len) : Vector3d::Zero();
  }
  // The lifts need the surface's normals far more accurately than facet averages give them (a
  // normal off by dn changes an edge's k by |e| dn, and k is |e|^2 / (2 R): 1e-3 rad on a
  // 20480-triangle icosphere is 5 % of the sag, 0.4 % of a soft contact's overlap). The
  // vertices lie on the surface, so each vertex's normal is taken from the quadric through its
  // neighbours instead (height over the averaged normal's plane, z = d x + e y + a x^2 + b x y
  // + c y^2, least squares): exact for a sphere to O(h^3 / R^3).
  const std::vector<Vector3d> averaged = normal;
  std::vector<std::vector<int>> ring(nv);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k)
      for (int j = 1; j < 3; ++j)
        ring[mesh.triangles[t][k]].push_back(mesh.triangles[t][(k + j) % 3]);
  for (std::size_t v = 0; v < nv; ++v) {
    std::vector<int> &r = ring[v];
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    normal[v] = fitted_normal(mesh, static_cast<int>(v), r, averaged[v]);
  }
  std::vector<double> deviation(nv, 0.0);
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[t][k];
      const double dev = face[t].isZero() || normal[v].isZero()
                             ? M_PI
                             : angle_between(face[t], normal[v]);
      deviation[v] = std::max(deviation[v], dev);
    }
  std::vector<double> smooth(nv);
  for (std::size_t v = 0; v < nv; ++v)
    smooth[v] = 1.0 - smoothstep01((deviation[v] - kSmoothVertexAngle) / kSmoothVertexAngle);
  std::vector<double> bulge(3 * static_cast<std::size_t>(nt), 0.0);
  bool any = false;
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = mesh.triangles[t][k], j = mesh.triangles[t][(k + 1) % 3];
      const double weight = smooth[i] * smooth[j];
      if (!(weight > 0.0))
        continue;
      const double kij =
          0.5 * weight * (mesh.vertices[i] - mesh.vertices[j]).dot(normal[i] - normal[j]);
      bulge[3 * static_cast<std::size_t>(t) + k] = kij;
      any = any || kij != 0.0;
    }
  if (!any)
    bulge.clear();
  return bulge;
}

double max_lift(const std::vector<double> &bulges) {
  double most = 0.0;
  for (std::size_t t = 0; 3 * t + 2 < bulges.size(); ++t) {
    const double *k = &bulges[3 * t];
    // On an edge (i, j) the lift is b_i b_j k_ij, at most k_ij / 4; inside, the stationary
    // point of b^T K b on b_0 + b_1 + b_2 = 1 (2 K b = lambda 1), where it lies inside.
    for (int e = 0; e < 3; ++e)
      most = std::max(most, 0.25 * k[e]);
    Eigen::Matrix4d system = Eigen::Matrix4d::Zero();
    system(0, 1) = system(1, 0) = k[0];
    system(1, 2) = system(2, 1) = k[1];
    system(2, 0) = system(0, 2) = k[2];
    for (int i = 0; i < 3; ++i)
      system(i, 3) = system(3, i) = 1.0;
    const Eigen::Vector4d rhs(0.0, 0.0, 0.0, 1.0);
    const Eigen::Vector4d sol = system.fullPivLu().solve(rhs);
    if (sol.head<3>().allFinite() && (sol.head<3>().array() >= 0.0).all() &&
        std::abs(sol.head<3>().sum() - 1.0) < 1e-9) {
      const double b0 = sol(0), b1 = sol(1), b2 = sol(2);
      most = std::max(most, b0 * b1 * k[0] + b1 * b2 * k[1] + b2 * b0 * k[2]);
    }
  }
  return most;
}

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
