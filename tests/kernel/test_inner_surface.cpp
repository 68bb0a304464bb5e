// inner_surface: the mesh offset inward by the soft layer; exact face planes where the shape
// allows, every face at least the layer behind elsewhere, errors for features too thin.
#include "body/inner_surface.h"
#include "body/random_rock.h"
#include "body/shape.h"
#include "geometry/point_triangle.h"
#include "test_meshes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <string>

namespace {

using Eigen::Vector3d;

Vector3d unit_normal(const tri::TriangleMesh &m, int t) {
  return (m.corner(t, 1) - m.corner(t, 0)).cross(m.corner(t, 2) - m.corner(t, 0)).normalized();
}

// Brute force: the distance from p to the nearest triangle of m.
double distance_to_surface(const tri::TriangleMesh &m, const Vector3d &p) {
  double best = std::numeric_limits<double>::infinity();
  for (int t = 0; t < m.num_triangles(); ++t)
    best = std::min(best, (tri::closest_point_on_triangle(p, m.corner(t, 0), m.corner(t, 1),
                                                          m.corner(t, 2)) -
                           p)
                              .norm());
  return best;
}

// How far behind its given plane each inner corner lies, over every triangle: [min, max].
std::pair<double, double> depth_behind_planes(const tri::TriangleMesh &given,
                                              const tri::TriangleMesh &inner) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int t = 0; t < given.num_triangles(); ++t) {
    const Vector3d n = unit_normal(given, t);
    for (int k = 0; k < 3; ++k) {
      const double depth = n.dot(given.corner(t, 0)) - n.dot(inner.corner(t, k));
      lo = std::min(lo, depth);
      hi = std::max(hi, depth);
    }
  }
  return {lo, hi};
}

TEST(ShortestInwardOffset, ThreeOrthogonalFacesMoveTheCornerAlongTheDiagonal) {
  Vector3d d;
  ASSERT_TRUE(tri::shortest_inward_offset({Vector3d::UnitX(), Vector3d::UnitY(), Vector3d::UnitZ()},
                                          0.1, d));
  EXPECT_NEAR((d - Vector3d(-0.1, -0.1, -0.1)).norm(), 0.0, 1e-15);
}

TEST(ShortestInwardOffset, RepeatedNormalsCountOnceAndAFlatVertexMovesAlongItsNormal) {
  Vector3d d;
  ASSERT_TRUE(tri::shortest_inward_offset({Vector3d::UnitZ(), Vector3d::UnitZ(), Vector3d::UnitZ()},
                                          0.25, d));
  EXPECT_NEAR((d - Vector3d(0, 0, -0.25)).norm(), 0.0, 1e-15);
}

TEST(ShortestInwardOffset, FourFacesOfAPyramidApexAllMoveByTheLayer) {
  const double s = 1.0 / std::sqrt(2.0);
  const std::vector<Vector3d> n = {{s, 0, s}, {-s, 0, s}, {0, s, s}, {0, -s, s}};
  Vector3d d;
  ASSERT_TRUE(tri::shortest_inward_offset(n, 0.1, d));
  for (const Vector3d &f : n)
    EXPECT_NEAR(f.dot(d), -0.1, 1e-14);
  EXPECT_NEAR(d.z(), -0.1 * std::sqrt(2.0), 1e-14);
}

TEST(ShortestInwardOffset, OppositeFacesAdmitNoOffset) {
  Vector3d d;
  EXPECT_FALSE(tri::shortest_inward_offset({Vector3d::UnitZ(), -Vector3d::UnitZ()}, 0.1, d));
}

TEST(InnerSurface, ACubeShrinksByTheLayerOnEverySide) {
  const tri::TriangleMesh inner = tri::inner_surface(tri_test::box(2, 2, 2), 0.1);
  for (const Vector3d &p : inner.vertices)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(std::min(std::abs(p[k] - 0.1), std::abs(p[k] - 1.9)), 0.0, 1e-15) << p.transpose();
}

TEST(InnerSurface, RegularSolidsMoveEveryFacePlaneByExactlyTheLayer) {
  const double layer = 0.05;
  for (const tri::TriangleMesh &m :
       {tri_test::tetrahedron(), tri_test::octasphere(0), tri_test::icosphere(0)}) {
    const tri::TriangleMesh inner = tri::inner_surface(m, layer);
    const auto [lo, hi] = depth_behind_planes(m, inner);
    EXPECT_NEAR(lo, layer, 1e-14);
    EXPECT_NEAR(hi, layer, 1e-14);
  }
}

TEST(InnerSurface, AnIcosphereKeepsEveryFaceAtLeastTheLayerBehindAndLittleMore) {
  const double layer = 0.02;
  const tri::TriangleMesh m = tri_test::icosphere(3); // 1280 triangles, unit radius
  const tri::TriangleMesh inner = tri::inner_surface(m, layer);
  const auto [lo, hi] = depth_behind_planes(m, inner);
  EXPECT_GE(lo, layer * (1.0 - 1e-9));
  EXPECT_LT(hi, layer * 1.01); // neighbouring normals within 0.09 rad: facets barely tilt
  for (const Vector3d &p : inner.vertices) {
    const double d = distance_to_surface(m, p);
    EXPECT_GE(d, layer * (1.0 - 1e-9));
    EXPECT_LT(d, layer * 1.01);
  }
}

TEST(InnerSurface, RandomRocksKeepEveryVertexTheLayerInside) {
  for (int ntri : {20, 40, 80}) {
    tri::RockParameters rock;
    rock.ntri = ntri;
    rock.size = 0.004;
    rock.seed = 7 + ntri;
    const tri::TriangleMesh m = tri::random_rock(rock);
    const double layer = 1e-4;
    const tri::TriangleMesh inner = tri::inner_surface(m, layer);
    EXPECT_GE(depth_behind_planes(m, inner).first, layer * (1.0 - 1e-9)) << ntri;
    for (const Vector3d &p : inner.vertices)
      EXPECT_GE(distance_to_surface(m, p), layer * (1.0 - 1e-6)) << ntri;
  }
}

TEST(InnerSurface, ANonConvexCornerMovesIntoTheSolidAlongBothFaces) {
  // tri_test::l_prism: vertex 3 is the concave corner (1,1,0), whose faces have outward
  // normals +y (from (2,1)) and +x (to (1,2)).
  const tri::TriangleMesh m = tri_test::l_prism(1.0);
  const double layer = 0.1;
  const tri::TriangleMesh inner = tri::inner_surface(m, layer);
  EXPECT_NEAR((inner.vertices[3] - Vector3d(0.9, 0.9, 0.1)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((inner.vertices[0] - Vector3d(0.1, 0.1, 0.1)).norm(), 0.0, 1e-14);
  for (const Vector3d &p : inner.vertices)
    EXPECT_GE(distance_to_surface(m, p), layer * (1.0 - 1e-9));
}

TEST(InnerSurface, AFeatureThinnerThanTwoLayersIsRefusedWithALayerThatFits) {
  const tri::TriangleMesh plate = tri_test::box(1, 1, 0.1);
  const std::string msg = tri_test::shape_error_message([&] { tri::inner_surface(plate, 0.06); });
  EXPECT_NE(msg.find("epsilon 0.06 m"), std::string::npos) << msg;
  EXPECT_NE(msg.find("thinner than 2 layers"), std::string::npos) << msg;
  EXPECT_NE(msg.find("epsilon 0.03 m would fit"), std::string::npos) << msg;
  EXPECT_NO_THROW(tri::inner_surface(plate, 0.03));
  EXPECT_DOUBLE_EQ(tri::largest_fitting_layer(plate, 0.2), 0.025);
}

TEST(InnerSurface, ALayerOfZeroIsTheMeshItself) {
  const tri::TriangleMesh m = tri_test::icosphere(1);
  const tri::TriangleMesh inner = tri::inner_surface(m, 0.0);
  EXPECT_EQ(inner.vertices, m.vertices);
}

TEST(WithSoftLayer, KeepsMassAndReachOfTheGivenMeshAndMeasuresTheInnerOne) {
  const tri::Shape given = tri::make_shape("cube", tri_test::box(2, 2, 2));
  const tri::Shape s = tri::with_soft_layer(given, 0.1);
  EXPECT_EQ(s.volume, given.volume);
  EXPECT_EQ(s.bounding_radius, given.bounding_radius);
  EXPECT_EQ(s.surface.x, given.surface.x);
  EXPECT_NEAR(s.inner_radius, 0.9 * std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(s.min_edge_length, 1.8, 1e-14);
  // The contact surface (inner cube grown by 0.1) reaches 0.9 sqrt(3) + 0.1 < sqrt(3).
  EXPECT_EQ(tri::contact_reach(s, 0.1), given.bounding_radius);
  // The layer outside the mesh: the given mesh grown by epsilon.
  EXPECT_NEAR(tri::contact_reach(given, 0.1), std::sqrt(3.0) + 0.1, 1e-14);
  const std::string msg = tri_test::shape_error_message([&] { tri::with_soft_layer(given, 1.5); });
  EXPECT_EQ(msg.rfind("shape 'cube': ", 0), 0u) << msg;
}

} // namespace
