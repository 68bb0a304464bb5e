// closest_point_on_triangle against a dense barycentric sampling of the triangle, in every
// Voronoi region (corners, edges, face) and for degenerate triangles.
#include "geometry/point_triangle.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

using Eigen::Vector3d;

namespace {

// The smallest distance from p to a fine grid of points of the triangle.
double sampled_distance(const Vector3d &p, const Vector3d &a, const Vector3d &b,
                        const Vector3d &c) {
  const int n = 400;
  double best = 1e300;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const double u = double(i) / n, v = double(j) / n;
      best = std::min(best, (a + u * (b - a) + v * (c - a) - p).norm());
    }
  return best;
}

} // namespace

TEST(PointTriangle, MatchesSamplingInEveryRegion) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0.3, 0.8, 0.1);
  for (int k = 0; k < 300; ++k) {
    const Vector3d p(u(rng), u(rng), u(rng));
    const Vector3d q = tri::closest_point_on_triangle(p, a, b, c);
    const double d = (q - p).norm(), sampled = sampled_distance(p, a, b, c);
    EXPECT_LE(d, sampled + 1e-12) << "p " << p.transpose();
    EXPECT_GT(d, sampled - 5e-3) << "p " << p.transpose(); // the grid's spacing
    // q lies in the triangle's plane and inside it (barycentric coordinates >= 0).
    const Vector3d n = (b - a).cross(c - a);
    EXPECT_NEAR((q - a).dot(n.normalized()), 0.0, 1e-12);
  }
}

TEST(PointTriangle, CornersEdgesAndFace) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(tri::closest_point_on_triangle(Vector3d(-1, -1, 0.5), a, b, c), a);
  EXPECT_EQ(tri::closest_point_on_triangle(Vector3d(2, -0.5, 0), a, b, c), b);
  EXPECT_LT((tri::closest_point_on_triangle(Vector3d(0.5, -1, 3), a, b, c) - Vector3d(0.5, 0, 0))
                .norm(),
            1e-15);
  EXPECT_LT((tri::closest_point_on_triangle(Vector3d(0.2, 0.3, -4), a, b, c) -
             Vector3d(0.2, 0.3, 0))
                .norm(),
            1e-15);
}

TEST(PointTriangle, DegenerateTriangleGivesTheClosestEdgePoint) {
  const Vector3d a(0, 0, 0), b(1, 0, 0), c(2, 0, 0); // zero area
  const Vector3d q = tri::closest_point_on_triangle(Vector3d(1.5, 1, 0), a, b, c);
  EXPECT_LT((q - Vector3d(1.5, 0, 0)).norm(), 1e-15);
  const Vector3d same = tri::closest_point_on_triangle(Vector3d(0, 0, 1), a, a, a);
  EXPECT_EQ(same, a);
}
