// Intersection helpers (triangle_intersection.h): edge-face crossings and the
// minimum-overlap normal of intersecting triangles.
#include "distance/triangle_distance.h"
#include "geometry/triangle_intersection.h"
#include "test_triangle_cases.h"

#include <gtest/gtest.h>

using namespace tri;
using V = Eigen::Vector3d;

TEST(TriangleIntersection, EdgeThroughFaceIsOneCrossingAtTheRightPoint) {
  const V a[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const V b[3] = {{0.2, 0.2, -1}, {0.3, 0.3, 1}, {2, 2, 0.5}};
  V pts[6];
  const int n = edge_face_crossings(a, b, pts);
  // b lies in the plane x = y: its edge pierces a at (0.25, 0.25, 0), and a's hypotenuse
  // pierces b at (0.5, 0.5, 0); the intersection is the segment between them.
  ASSERT_EQ(n, 2);
  EXPECT_NEAR((pts[0] - V(0.5, 0.5, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((pts[1] - V(0.25, 0.25, 0)).norm(), 0.0, 1e-15);
}

TEST(TriangleIntersection, SeparatedAndCoplanarPairsHaveNoCrossing) {
  const V a[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const V above[3] = {{0, 0, 1e-9}, {1, 0, 1e-9}, {0, 1, 1e-9}};
  const V coplanar[3] = {{0.2, 0.2, 0}, {1.2, 0.2, 0}, {0.2, 1.2, 0}};
  V pts[6];
  EXPECT_EQ(edge_face_crossings(a, above, pts), 0);
  EXPECT_EQ(edge_face_crossings(a, coplanar, pts), 0); // seen by the 15 checks instead
}

TEST(TriangleIntersection, PenetratingFaceNormalIsTheFaceNormalFromAToB) {
  // b's face dips 1e-3 below a's plane while lying above it elsewhere: the smallest
  // separating translation is along +z (a's normal), by the dip.
  const V a[3] = {{-1, -1, 0}, {2, -1, 0}, {-1, 2, 0}};
  const V b[3] = {{0.2, 0.2, -1e-3}, {0.6, 0.2, 0.05}, {0.2, 0.6, 0.05}};
  const SeparatingAxis s = min_overlap_axis(a, b);
  EXPECT_NEAR((s.normal - V::UnitZ()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(s.depth, 1e-3, 1e-15);
  // Swapping the triangles flips the normal.
  const SeparatingAxis t = min_overlap_axis(b, a);
  EXPECT_NEAR(t.normal.dot(s.normal), -1.0, 1e-9);
}

TEST(TriangleIntersection, CoplanarOverlapUsesThePlaneNormalTowardsB) {
  const V a[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const V b[3] = {{0.2, 0.2, 0}, {1.2, 0.2, 0}, {0.2, 1.2, 0}};
  const SeparatingAxis s = min_overlap_axis(a, b);
  EXPECT_NEAR(std::abs(s.normal.z()), 1.0, 1e-15);
  EXPECT_EQ(s.depth, 0.0);
}

TEST(TriangleIntersection, DegenerateInputStillGivesAUnitNormal) {
  const V a[3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const V b[3] = {{0.5, 0, 0}, {1.5, 0, 0}, {3, 0, 0}};
  const SeparatingAxis s = min_overlap_axis(a, b);
  EXPECT_NEAR(s.normal.norm(), 1.0, 1e-15);
  const V p[3] = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  const SeparatingAxis t = min_overlap_axis(p, p);
  EXPECT_NEAR(t.normal.norm(), 1.0, 1e-15);
}

TEST(TriangleIntersection, EveryCrossingCaseIntersectsWithAFiniteNormal) {
  for (double scale : {1e-6, 1.0, 1e3})
    for (const auto &c : tri_test::adversarial_cases(scale, 21)) {
      const TrianglePairDistance r = triangle_distance(c.a, c.b);
      if (!c.intersecting)
        continue;
      EXPECT_TRUE(r.intersecting) << c.name;
      EXPECT_TRUE(r.normal.allFinite()) << c.name;
      EXPECT_NEAR(r.normal.norm(), 1.0, 1e-12) << c.name;
      EXPECT_TRUE(std::isfinite(r.penetration_depth)) << c.name;
    }
}
