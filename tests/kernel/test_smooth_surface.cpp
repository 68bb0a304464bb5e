// smooth_surface.h: the lifts of a finely meshed ball rebuild its sphere; facets that are the
// body (a cube, a rock) get none; the smooth peak of a ball on a plane is the sphere's. The
// corners' spheres of a ball are its sphere, and two balls meet as their spheres
// (contact/ball_contact.h); a cube, a rock, a flat plate and an ellipsoid are no balls.
#include "body/random_rock.h"
#include "body/smooth_surface.h"
#include "contact/ball_contact.h"
#include "contact/contact_polygon.h"
#include "contact/smooth_peak.h"
#include "geometry/triangle_soa.h"
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

TEST(SmoothSurface, CornerSpheresOfAnIcosphereAreItsSphere) {
  for (int level : {3, 4, 5}) {
    const tri::TriangleMesh ball = tri_test::icosphere(level); // unit sphere
    const std::vector<tri::SurfaceSphere> spheres = tri::corner_spheres(ball);
    ASSERT_EQ(spheres.size(), 3 * ball.triangles.size());
    double worst_centre = 0.0, worst_radius = 0.0, least_weight = 1.0;
    for (const tri::SurfaceSphere &s : spheres) {
      worst_centre = std::max(worst_centre, s.centre.norm());
      worst_radius = std::max(worst_radius, std::abs(s.radius - 1.0));
      least_weight = std::min(least_weight, s.weight);
    }
    // Points on a sphere determine it up to rounding (the fit's condition ~ (R / h)^2).
    EXPECT_LT(worst_centre, 1e-10) << "level " << level;
    EXPECT_LT(worst_radius, 1e-10) << "level " << level;
    EXPECT_EQ(least_weight, 1.0) << "level " << level;
    // The sphere rises above the facets by their sag: R (1 - cos(half the facet's angle)).
    double sag = 0.0;
    for (int t = 0; t < ball.num_triangles(); ++t) {
      const Vector3d p0 = ball.corner(t, 0);
      const Vector3d n = (ball.corner(t, 1) - p0).cross(ball.corner(t, 2) - p0).normalized();
      sag = std::max(sag, 1.0 - p0.dot(n));
    }
    EXPECT_NEAR(tri::max_ball_sag(ball, spheres), sag, 1e-10) << "level " << level;
  }
}

TEST(SmoothSurface, BodiesThatAreNoBallsGetNoSpheres) {
  EXPECT_TRUE(tri::corner_spheres(tri_test::box()).empty());
  // A 320-triangle icosphere is too coarse: the sphere through its vertices is 3.5 % larger.
  EXPECT_TRUE(tri::corner_spheres(tri_test::icosphere(2)).empty());
  tri::RockParameters rock;
  rock.ntri = 40;
  rock.size = 0.004;
  rock.seed = 7;
  EXPECT_TRUE(tri::corner_spheres(tri::random_rock(rock)).empty());
  // An ellipsoid of axes 1, 1, 0.6: smooth, but round only about its poles (an umbilic, radius
  // 1 / 0.6); about its equator its curvatures differ by 2.8 times and no sphere fits.
  tri::TriangleMesh ellipsoid = tri_test::icosphere(4);
  for (Vector3d &v : ellipsoid.vertices)
    v.z() *= 0.6;
  const std::vector<tri::SurfaceSphere> spheres = tri::corner_spheres(ellipsoid);
  ASSERT_EQ(spheres.size(), 3 * ellipsoid.triangles.size());
  double equator = 0.0, pole = 1.0;
  for (int t = 0; t < ellipsoid.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const double z = std::abs(ellipsoid.corner(t, k).z());
      if (z < 0.3)
        equator = std::max(equator, spheres[3 * t + k].weight);
      if (z > 0.59)
        pole = std::min(pole, spheres[3 * t + k].weight);
    }
  EXPECT_EQ(equator, 0.0);
  EXPECT_GT(pole, 0.9);
}

// Two unit icospheres of level 4, turned at random, their centres d apart along a random line,
// through the reduction's contact point (ball_contacts reads its triangles and point): the
// contact is the spheres', overlap 2 - d on the line of centres, the point midway through it.
TEST(BallContact, TwoIcospheresMeetAsSpheres) {
  const tri::TriangleMesh ball = tri_test::icosphere(4);
  const std::vector<tri::SurfaceSphere> spheres = tri::corner_spheres(ball);
  const tri::TriangleSoA body = tri::to_soa(ball);
  for (int trial = 0; trial < 6; ++trial) {
    const Eigen::Quaterniond qa(Eigen::AngleAxisd(0.3 + trial, Vector3d(1, 2, 3 - trial).normalized()));
    const Eigen::Quaterniond qb(Eigen::AngleAxisd(1.1 * trial, Vector3d(-2, trial, 1).normalized()));
    const Vector3d line = Vector3d(std::cos(trial), std::sin(2.0 * trial), 0.4).normalized();
    const double d = 2.0 - 1e-3 * (1 + trial);
    const Vector3d xa(0.1, -0.2, 0.3), xb = xa + d * line;
    tri::TriangleSoA wa = body, wb = body;
    for (std::size_t k = 0; k < wa.x.size(); ++k) {
      const Vector3d pa = xa + qa * Vector3d(body.x[k], body.y[k], body.z[k]);
      const Vector3d pb = xb + qb * Vector3d(body.x[k], body.y[k], body.z[k]);
      wa.x[k] = pa.x(), wa.y[k] = pa.y(), wa.z[k] = pa.z();
      wb.x[k] = pb.x(), wb.y[k] = pb.y(), wb.z[k] = pb.z();
    }
    // The facets nearest the line of centres on either side, as the reduction would name them.
    auto nearest = [&](const tri::TriangleSoA &t, const Vector3d &target) {
      int best = 0;
      double best_d2 = 1e300;
      for (int k = 0; k < t.num_triangles(); ++k) {
        const Vector3d c = (t.vertex(k, 0) + t.vertex(k, 1) + t.vertex(k, 2)) / 3.0;
        if ((c - target).squaredNorm() < best_d2) {
          best_d2 = (c - target).squaredNorm();
          best = k;
        }
      }
      return best;
    };
    const Vector3d mid = xa + 0.5 * d * line;
    std::vector<tri::ContactPoint> points(1);
    points[0].tri_a = nearest(wa, mid);
    points[0].tri_b = nearest(wb, mid);
    points[0].point = mid + Vector3d(1e-3, -2e-3, 0.0); // the facets' point is off the line
    points[0].normal = Vector3d(0.1, 0.0, 1.0).normalized();
    points[0].overlap = points[0].energy_overlap = 1e-4;
    tri::ball_contacts({&wa, spheres.data(), xa, qa, 0.0}, {&wb, spheres.data(), xb, qb, 0.0},
                       points);
    ASSERT_EQ(points.size(), 1u);
    EXPECT_NEAR(points[0].overlap, 2.0 - d, 1e-12) << "trial " << trial;
    EXPECT_NEAR(points[0].energy_overlap, 2.0 - d, 1e-12);
    EXPECT_LT((points[0].normal - line).norm(), 1e-12);
    EXPECT_LT((points[0].point - mid).norm(), 1e-12);
  }
}

// Spheres apart (their facets within the widened layer, the spheres not yet touching): no
// contact point is left.
TEST(BallContact, SpheresApartLeaveNoPoint) {
  const tri::TriangleMesh ball = tri_test::icosphere(3);
  const std::vector<tri::SurfaceSphere> spheres = tri::corner_spheres(ball);
  const tri::TriangleSoA body = tri::to_soa(ball);
  tri::TriangleSoA wb = body;
  for (double &x : wb.x)
    x += 2.0 + 1e-6;
  std::vector<tri::ContactPoint> points(1);
  points[0].tri_a = 0;
  points[0].tri_b = 0;
  points[0].overlap = 1e-4;
  const Eigen::Quaterniond id = Eigen::Quaterniond::Identity();
  tri::ball_contacts({&body, spheres.data(), Vector3d::Zero(), id, 0.0},
                     {&wb, spheres.data(), Vector3d(2.0 + 1e-6, 0, 0), id, 0.0}, points);
  EXPECT_TRUE(points.empty());
}

} // namespace
