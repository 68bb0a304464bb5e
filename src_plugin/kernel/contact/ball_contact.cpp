#include "contact/ball_contact.h"

#include "geometry/point_triangle.h"

#include <algorithm>
#include <cmath>

namespace tri {

using Eigen::Vector3d;

namespace {

// Barycentric coordinates of q, a point of triangle (p0, p1, p2) (closest_point_on_triangle's),
// clamped to the triangle against rounding; the centroid for a triangle of no area.
Vector3d barycentric(const Vector3d &q, const Vector3d &p0, const Vector3d &p1,
                     const Vector3d &p2) {
  const Vector3d e1 = p1 - p0, e2 = p2 - p0, d = q - p0;
  const double a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2);
  const double det = a11 * a22 - a12 * a12;
  if (!(det > 0.0))
    return Vector3d::Constant(1.0 / 3.0);
  const double b1 = (a22 * e1.dot(d) - a12 * e2.dot(d)) / det;
  const double b2 = (a11 * e2.dot(d) - a12 * e1.dot(d)) / det;
  Vector3d b(1.0 - b1 - b2, b1, b2);
  b = b.cwiseMax(0.0);
  return b / b.sum();
}

// The blend of step t between two values.
template <class T> T blend(const T &facets, const T &ball, double t) {
  return facets + t * (ball - facets);
}

} // namespace

SurfaceSphere ball_at(const BallSide &side, int triangle, const Vector3d &point) {
  const TriangleSoA &t = *side.triangles;
  const Vector3d p0 = t.vertex(triangle, 0), p1 = t.vertex(triangle, 1), p2 = t.vertex(triangle, 2);
  const Vector3d b = barycentric(closest_point_on_triangle(point, p0, p1, p2), p0, p1, p2);
  const SurfaceSphere *corner = side.spheres + 3 * static_cast<std::size_t>(triangle);
  SurfaceSphere s;
  Vector3d centre = Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    centre += b[k] * corner[k].centre;
    s.radius += b[k] * corner[k].radius;
    s.weight += b[k] * corner[k].weight;
  }
  s.centre = side.x + side.q * centre;
  s.radius += side.epsilon;
  return s;
}

void ball_contacts(const BallSide &a, const BallSide &b, std::vector<ContactPoint> &points) {
  for (ContactPoint &p : points) {
    if (p.intersecting || p.tri_a < 0 || p.tri_b < 0)
      continue;
    const SurfaceSphere sa = ball_at(a, p.tri_a, p.point), sb = ball_at(b, p.tri_b, p.point);
    const double t = sa.weight * sb.weight;
    if (!(t > 0.0))
      continue;
    const Vector3d line = sb.centre - sa.centre;
    const double distance = line.norm();
    if (!(distance > 0.0))
      continue; // concentric: no direction (the facets' point stands)
    const Vector3d n = line / distance;
    const double overlap = sa.radius + sb.radius - distance;
    const Vector3d point = sa.centre + (sa.radius - 0.5 * overlap) * n;
    p.overlap = blend(p.overlap, overlap, t);
    p.energy_overlap = blend(p.energy_overlap, overlap, t);
    p.normal = blend(p.normal, n, t).normalized();
    p.point = blend(p.point, point, t);
    p.damping_point = blend(p.damping_point, point, t);
    p.face_weight *= 1.0 - t;
    p.patch_area *= 1.0 - t;
    p.patch_second_moment *= 1.0 - t;
    p.patch_mean_radius *= 1.0 - t;
  }
  points.erase(std::remove_if(points.begin(), points.end(),
                              [](const ContactPoint &p) { return !(p.overlap > 0.0); }),
               points.end());
}

} // namespace tri
