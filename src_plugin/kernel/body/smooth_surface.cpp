#include "body/smooth_surface.h"

#include <algorithm>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <limits>

namespace tri {

namespace {

using Eigen::Vector3d;

double smoothstep01(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

double angle_between(const Vector3d &u, const Vector3d &v) {
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

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

// Each vertex's normal (the quadric fit below), the largest angle of its facets from it (rad),
// its smoothness (1 smooth, 0 a corner of the body), and its ring of neighbours.
struct VertexFrames {
  std::vector<Vector3d> normal;
  std::vector<double> deviation;
  std::vector<double> smooth;
  std::vector<std::vector<int>> ring;
};

VertexFrames vertex_frames(const TriangleMesh &mesh) {
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
  return {std::move(normal), std::move(deviation), std::move(smooth), std::move(ring)};
}

// The sphere through vertex p and its ring: the centre p + u with 2 u . d = |d|^2 for every
// neighbour at p + d, least squares (exact for points on a sphere, whatever the normals). The
// vertex's ball weight fades from 1 to 0 where that sphere stops describing the surface: where
// the facets are too coarse for it (kBallVertexAngle: its sag would be more than 0.6 % of the
// radius), where it bends too little to tell from a plane (a flat face, where
// the facets are exact), where the ring leaves the sphere by more than a share of its sag (a
// cylinder, an ellipsoid's flanks: a sphere is the wrong body there), or where it is concave.
SurfaceSphere ring_sphere(const TriangleMesh &mesh, int v, const std::vector<int> &ring,
                          const Vector3d &normal, double deviation) {
  SurfaceSphere s;
  s.centre = mesh.vertices[v];
  const double fine =
      1.0 - smoothstep01((deviation - kBallVertexAngle) / (kSmoothVertexAngle - kBallVertexAngle));
  if (!(fine > 0.0) || ring.size() < 4 || normal.isZero())
    return s;
  const Vector3d p = mesh.vertices[v];
  Eigen::Matrix<double, Eigen::Dynamic, 3> A(ring.size(), 3);
  Eigen::VectorXd rhs(ring.size());
  double h = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vector3d d = mesh.vertices[ring[i]] - p;
    A.row(i) = d.transpose();
    rhs(i) = 0.5 * d.squaredNorm();
    h = std::max(h, d.norm());
  }
  const Eigen::ColPivHouseholderQR<Eigen::Matrix<double, Eigen::Dynamic, 3>> qr(A);
  if (qr.rank() < 3)
    return s;
  const Vector3d u = qr.solve(rhs);
  const double radius = u.norm();
  if (!std::isfinite(radius) || !(radius > 0.0) || u.dot(normal) >= 0.0)
    return s; // no sphere, or a concave one
  double misfit = 0.0, sag = 0.0;
  for (int q : ring) {
    const Vector3d d = mesh.vertices[q] - p;
    misfit = std::max(misfit, std::abs((d - u).norm() - radius));
    sag = std::max(sag, 0.5 * d.squaredNorm() / radius);
  }
  const double bend = h / radius; // the angle the surface turns over one edge, rad
  const double curved = smoothstep01((bend - kBallMinBend) / kBallMinBend);
  const double fits = 1.0 - smoothstep01((misfit / sag - kBallMisfit) / kBallMisfit);
  s.centre = p + u;
  s.radius = radius;
  s.weight = fine * curved * fits;
  return s;
}

} // namespace

std::vector<double> edge_bulges(const TriangleMesh &mesh) {
  const int nt = mesh.num_triangles();
  const VertexFrames frames = vertex_frames(mesh);
  const std::vector<Vector3d> &normal = frames.normal;
  const std::vector<double> &smooth = frames.smooth;
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

std::vector<SurfaceSphere> corner_spheres(const TriangleMesh &mesh) {
  const VertexFrames frames = vertex_frames(mesh);
  const std::size_t nv = mesh.vertices.size();
  std::vector<SurfaceSphere> vertex(nv);
  bool any = false;
  for (std::size_t v = 0; v < nv; ++v) {
    vertex[v] = ring_sphere(mesh, static_cast<int>(v), frames.ring[v], frames.normal[v],
                            frames.deviation[v]);
    any = any || vertex[v].weight > 0.0;
  }
  std::vector<SurfaceSphere> corners;
  if (!any)
    return corners;
  corners.reserve(3 * static_cast<std::size_t>(mesh.num_triangles()));
  for (const auto &t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      corners.push_back(vertex[t[k]]);
  return corners;
}

double max_ball_sag(const TriangleMesh &mesh, const std::vector<SurfaceSphere> &corners) {
  double most = 0.0;
  for (std::size_t t = 0; 3 * t + 2 < corners.size(); ++t) {
    const Vector3d p0 = mesh.corner(static_cast<int>(t), 0);
    const Vector3d n = (mesh.corner(static_cast<int>(t), 1) - p0)
                           .cross(mesh.corner(static_cast<int>(t), 2) - p0)
                           .normalized();
    for (int k = 0; k < 3; ++k) {
      const SurfaceSphere &s = corners[3 * t + k];
      if (s.weight > 0.0 && n.allFinite()) // the sphere's top above the facet's plane
        most = std::max(most, s.radius - (p0 - s.centre).dot(n));
    }
  }
  return most;
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

} // namespace tri
