// smooth_surface.h: the lifts of a finely meshed ball rebuild its sphere; facets that are the
// body (a cube, a rock) get none; the smooth peak of a ball on a plane is the sphere's.
#include "body/random_rock.h"
#include "body/smooth_surface.h"
#include "contact/contact_polygon.h"
#include "contact/smooth_peak.h"
#include "test_meshes.h"

#include <Eigen/Geometry>
#include <cmath>
#include <gtest/gtest.h>

namespace {

using Eigen::Vector3d;

// The lift at barycentric b of triangle t (edges (0,1), (1,2), (2,0)).
double lift_at(const std::vector<double> &bulge, int t, const Vector3d &b) {
  const double *k = &bulge[3 * t];
  return b[0] * b[1] * k[0] + b[1] * b[2] * k[1] + b[2] * b[0] * k[2];
}

TEST(SmoothSurface, IcosphereLiftsRebuildTheSphere) {
  for (int level : {3, 4, 5}) {
    const tri::TriangleMesh ball = tri_test::icosphere(level); // unit sphere
    const std::vector<double> bulge = tri::edge_bulges(ball);
    ASSERT_EQ(bulge.size(), 3 * ball.triangles.size());
    double worst = 0.0, worst_sag = 0.0;
    for (int t = 0; t < ball.num_triangles(); ++t) {
      const Vector3d p0 = ball.corner(t, 0), p1 = ball.corner(t, 1), p2 = ball.corner(t, 2);
      const Vector3d n = (p1 - p0).cross(p2 - p0).normalized();
      for (const Vector3d &b : {Vector3d(1.0 / 3, 1.0 / 3, 1.0 / 3), Vector3d(0.5, 0.25, 0.25),
                                Vector3d(0.1, 0.6, 0.3)}) {
        const Vector3d chord = b[0] * p0 + b[1] * p1 + b[2] * p2;
        // The unit sphere's height above the chord plane along its normal, at that point.
        const double c = chord.dot(n), q = (chord - c * n).squaredNorm();
        const double sphere = std::sqrt(1.0 - q) - c;
        worst = std::max(worst, std::abs(lift_at(bulge, t, b) - sphere));
        worst_sag = std::max(worst_sag, sphere);
      }
    }
    // Exact to second order: the error is far below the sag itself (h^4 against h^2).
    EXPECT_LT(worst, 0.02 * worst_sag) << "level " << level;
    EXPECT_NEAR(tri::max_lift(bulge), worst_sag, 0.1 * worst_sag) << "level " << level;
  }
}

TEST(SmoothSurface, FacetsThatAreTheBodyGetNoLift) {
  EXPECT_TRUE(tri::edge_bulges(tri_test::box()).empty());
  tri::RockParameters rock;
  rock.ntri = 40;
  rock.size = 0.004;
  rock.seed = 7;
  EXPECT_TRUE(tri::edge_bulges(tri::random_rock(rock)).empty());
  EXPECT_EQ(tri::max_lift({}), 0.0);
}

TEST(SmoothSurface, PeakOfABallFacetOnAPlaneIsTheSpheres) {
  // A level-5 unit ball's lowest facets over the plane z = -1 + d (d the sphere's overlap with
  // the plane, no soft layer beyond the plane): each facet's polygon with the plane, its peak
  // on the smooth surface; the largest over the facets must be d, under the centre.
  const tri::TriangleMesh ball = tri_test::icosphere(5);
  const std::vector<double> bulge = tri::edge_bulges(ball);
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.37, Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  const double d = 2e-3; // about 3.5 sags
  const double plane = -1.0 + d;
  const Vector3d w0(-10, -10, plane), w1(10, -10, plane), w2(0, 20, plane);
  const Vector3d wall[3] = {w0, w1, w2};
  double best = -1.0;
  Vector3d best_point = Vector3d::Zero(), best_normal = Vector3d::Zero();
  for (int t = 0; t < ball.num_triangles(); ++t) {
    const Vector3d a[3] = {turn * ball.corner(t, 0), turn * ball.corner(t, 1),
                           turn * ball.corner(t, 2)};
    if (std::min({a[0].z(), a[1].z(), a[2].z()}) > plane + 0.01)
      continue;
    tri::ContactPolygon poly;
    // layer 0 widened by the ball's largest lift, as the reduction does.
    const double lift = tri::max_lift(bulge);
    if (!tri::contact_polygon(a[0], a[1], a[2], wall[0], wall[1], wall[2], Vector3d(0, 0, -1),
                              lift, poly) ||
        !(poly.area > 0.0))
      continue;
    const tri::SmoothPeak peak = tri::smooth_peak(poly, a, &bulge[3 * t], wall, nullptr, lift);
    if (peak.overlap > best) {
      best = peak.overlap;
      best_point = peak.point;
      best_normal = peak.normal;
    }
  }
  EXPECT_NEAR(best, d, 2e-3 * d);
  EXPECT_NEAR(best_point.x(), 0.0, 1e-4);
  EXPECT_NEAR(best_point.y(), 0.0, 1e-4);
  EXPECT_NEAR(std::abs(best_normal.z()), 1.0, 1e-9);
}

} // namespace
