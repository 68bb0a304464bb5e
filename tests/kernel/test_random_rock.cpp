// Random rocks: exact triangle counts, closed valid convex shapes, bounding diameter ==
// size, determinism, aspect ratios, parameter checks.
#include "body/random_rock.h"
#include "body/shape.h"
#include "test_meshes.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <string>

namespace {

tri::RockParameters rock(int ntri, std::uint64_t seed, double size = 0.004) {
  tri::RockParameters p;
  p.ntri = ntri;
  p.size = size;
  p.seed = seed;
  return p;
}

constexpr double kPi = 3.14159265358979323846;

// Lower bounds on volume / bounding-ball volume, a little below the smallest of seeds 0-199.
double min_ball_fraction(int ntri) {
  switch (ntri) {
  case 4:
    return 0.02;
  case 20:
    return 0.2;
  case 40:
    return 0.4;
  default:
    return 0.6;
  }
}

class RockCounts : public ::testing::TestWithParam<int> {};

TEST_P(RockCounts, ExactTrianglesClosedConvexAndSized) {
  const int ntri = GetParam();
  const double size = 0.004;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const tri::TriangleMesh mesh = tri::random_rock(rock(ntri, seed, size));
    ASSERT_EQ(mesh.num_triangles(), ntri);
    ASSERT_EQ(mesh.num_vertices(), (ntri + 4) / 2); // every point is a hull vertex
    tri::Shape shape;
    ASSERT_NO_THROW(shape = tri::make_shape("rock", mesh)); // closed, oriented, outward
    EXPECT_TRUE(shape.convex);
    EXPECT_NEAR(2.0 * shape.bounding_radius, size, 1e-12 * size);
    // No slivers: edges are a sizeable fraction of the typical spacing.
    EXPECT_GT(shape.min_edge_length, 0.1 * size / std::sqrt(static_cast<double>(ntri)));
    // Not flat: the rock fills a fair part of its bounding ball (a regular tetrahedron
    // fills 12 %; without the dihedral-angle rejection some tetrahedra fill 0.0 %).
    EXPECT_GT(shape.volume / (kPi / 6.0 * std::pow(size, 3)), min_ball_fraction(ntri));
  }
}

INSTANTIATE_TEST_SUITE_P(RandomRock, RockCounts, ::testing::Values(4, 20, 40, 100));

TEST(RandomRock, LargeTriangleCounts) {
  for (int ntri : {500, 2000}) {
    const tri::Shape shape = tri::make_shape("rock", tri::random_rock(rock(ntri, 1)));
    EXPECT_EQ(shape.mesh.num_triangles(), ntri);
    EXPECT_TRUE(shape.convex);
  }
}

TEST(RandomRock, SameSeedSameMeshOtherSeedOtherMesh) {
  const tri::TriangleMesh a = tri::random_rock(rock(40, 7));
  const tri::TriangleMesh b = tri::random_rock(rock(40, 7));
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    EXPECT_EQ(a.vertices[i], b.vertices[i]) << "vertex " << i; // bit for bit
  EXPECT_EQ(a.triangles, b.triangles);
  const tri::TriangleMesh c = tri::random_rock(rock(40, 8));
  EXPECT_NE(a.vertices[0], c.vertices[0]);
}

TEST(RandomRock, FirstVertexIsPinned) {
  // Guards the portability claim: the mapping from std::mt19937_64's raw output (fixed by the
  // C++ standard) is our own, so this value must not change between standard libraries.
  // If the algorithm is changed on purpose, update the value.
  const tri::TriangleMesh m = tri::random_rock(rock(20, 42, 1.0));
  // Not bit-exact: std::cos / std::sin may differ in the last bit between libm versions.
  EXPECT_NEAR(m.vertices[0].x(), -0.24173477830536896, 1e-12);
  EXPECT_NEAR(m.vertices[0].y(), -0.31176686553194266, 1e-12);
  EXPECT_NEAR(m.vertices[0].z(), 0.26310720564133022, 1e-12);
  EXPECT_EQ(m.triangles[0], (std::array<int, 3>{0, 5, 6}));
}

TEST(RandomRock, AspectRatiosShapeTheRock) {
  tri::RockParameters p = rock(100, 3);
  p.aspect_middle = 0.6;
  p.aspect_short = 0.3;
  const tri::Shape shape = tri::make_shape("rock", tri::random_rock(p));
  EXPECT_TRUE(shape.convex);
  EXPECT_NEAR(2.0 * shape.bounding_radius, p.size, 1e-12 * p.size);
  // Body frame: x along the smallest moment (the long axis). Extents follow the aspects.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  for (const auto &v : shape.mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const Eigen::Vector3d extent = hi - lo;
  EXPECT_NEAR(extent.y() / extent.x(), 0.6, 0.06);
  EXPECT_NEAR(extent.z() / extent.x(), 0.3, 0.03);
}

TEST(RandomRock, StronglyElongatedRocksAreStillValid) {
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    tri::RockParameters p = rock(40, seed);
    p.aspect_middle = 0.5;
    p.aspect_short = 0.1;
    tri::Shape shape;
    ASSERT_NO_THROW(shape = tri::make_shape("rock", tri::random_rock(p))) << "seed " << seed;
    EXPECT_TRUE(shape.convex);
  }
}

// The message of the ShapeError random_rock throws, or "" if it accepts the parameters.
std::string rock_error(const tri::RockParameters &p) {
  return tri_test::shape_error_message([&] { tri::random_rock(p); });
}

TEST(RandomRock, BadParametersThrowNamingTheValue) {
  for (int ntri : {21, 3, 2, 0, -4}) {
    const std::string msg = rock_error(rock(ntri, 1));
    EXPECT_NE(msg.find("ntri must be even and at least 4"), std::string::npos) << msg;
    EXPECT_NE(msg.find("got " + std::to_string(ntri)), std::string::npos) << msg;
  }
  for (double size : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                      std::numeric_limits<double>::infinity()}) {
    const std::string msg = rock_error(rock(20, 1, size));
    EXPECT_NE(msg.find("size must be positive and finite"), std::string::npos) << msg;
  }
  tri::RockParameters p = rock(20, 1);
  p.aspect_middle = 0.0;
  EXPECT_EQ(rock_error(p), "random rock: aspect_middle must be in (0, 1], got 0");
  p.aspect_middle = 1.5;
  EXPECT_EQ(rock_error(p), "random rock: aspect_middle must be in (0, 1], got 1.5");
  p.aspect_middle = 1.0;
  p.aspect_short = -0.1;
  EXPECT_EQ(rock_error(p), "random rock: aspect_short must be in (0, 1], got -0.1");
  EXPECT_EQ(rock_error(rock(21, 1)),
            "random rock: ntri must be even and at least 4 (a closed triangulated convex "
            "surface with n vertices has 2n - 4 triangles), got 21");
}

} // namespace
