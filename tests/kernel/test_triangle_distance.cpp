// Brute-force triangle distance (triangle_distance.h) against FCL's triangle distance on a
// million seeded random pairs, and against distances known by construction on the
// adversarial sets at scales 1e-6 .. 1e3.
#include "distance/triangle_distance.h"
#include "test_triangle_cases.h"

#include <fcl/narrowphase/detail/primitive_shape_algorithm/triangle_distance.h>
#include <gtest/gtest.h>

#include <random>

#include <Eigen/Geometry>

using namespace tri;
using namespace tri_test;

namespace {

// Distance from x to the closed triangle t, by an independent method: least-squares
// barycentric coordinates of x's projection (inside: the plane distance), else the nearest
// of the three edges, each by clamped projection.
double distance_to_triangle(const Eigen::Vector3d &x, const Eigen::Vector3d t[3]) {
  Eigen::Matrix<double, 3, 2> m;
  m << t[1] - t[0], t[2] - t[0];
  const Eigen::Vector2d uv = (m.transpose() * m).ldlt().solve(m.transpose() * (x - t[0]));
  if (uv.minCoeff() >= 0 && uv.sum() <= 1)
    return (t[0] + m * uv - x).norm();
  double best = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d p = t[k], d = t[(k + 1) % 3] - t[k];
    const double s = std::clamp((x - p).dot(d) / d.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p + s * d - x).norm());
  }
  return best;
}

void expect_valid(const TrianglePairDistance &r, const std::string &what) {
  EXPECT_TRUE(std::isfinite(r.distance)) << what;
  EXPECT_GE(r.distance, 0.0) << what;
  EXPECT_NEAR(r.normal.norm(), 1.0, 1e-12) << what;
  EXPECT_NEAR((r.point_b - r.point_a).norm(), r.distance, 1e-12 * (1 + r.distance)) << what;
  EXPECT_EQ(r.intersecting, r.distance == 0.0) << what;
}

} // namespace

TEST(TriangleDistance, MatchesFclOnAMillionRandomPairs) {
  std::mt19937_64 rng(20240601);
  const int n = 1000000;
  int intersecting = 0;
  double worst = 0.0;
  for (int k = 0; k < n; ++k) {
    Eigen::Vector3d a[3], b[3];
    const Eigen::Vector3d offset(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    for (int v = 0; v < 3; ++v) {
      a[v] = {uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1)};
      b[v] = Eigen::Vector3d(uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1)) + offset;
    }
    const TrianglePairDistance r = triangle_distance(a, b);
    Eigen::Vector3d p, q;
    const double d_fcl = fcl::detail::TriangleDistance<double>::triDistance(a, b, p, q);
    worst = std::max(worst, std::abs(r.distance - d_fcl));
    ASSERT_NEAR(r.distance, d_fcl, 1e-12) << "pair " << k;
    intersecting += r.intersecting;
    if (k % 2000 == 0) { // points lie on their triangles and realise the distance
      expect_valid(r, "pair " + std::to_string(k));
      ASSERT_LT(distance_to_triangle(r.point_a, a), 1e-10) << "pair " << k;
      ASSERT_LT(distance_to_triangle(r.point_b, b), 1e-10) << "pair " << k;
    }
  }
  // The set must exercise both outcomes.
  EXPECT_GT(intersecting, n / 100);
  EXPECT_LT(intersecting, n / 2);
  RecordProperty("worst_abs_difference", std::to_string(worst));
}

TEST(TriangleDistance, MatchesFclOnAdversarialSetsAtUnitScale) {
  for (const auto &c : adversarial_cases(1.0, 11)) {
    const TrianglePairDistance r = triangle_distance(c.a, c.b);
    Eigen::Vector3d p, q;
    const double d_fcl = fcl::detail::TriangleDistance<double>::triDistance(c.a, c.b, p, q);
    // FCL treats slivers by their (tiny) face too; allow the sliver width.
    const double tol = c.name.find("sliver") != std::string::npos ? 1e-9 : 1e-12;
    EXPECT_NEAR(r.distance, d_fcl, tol) << c.name;
  }
}

class TriangleDistanceAtScale : public ::testing::TestWithParam<double> {};

TEST_P(TriangleDistanceAtScale, KnownDistancesOfAdversarialSets) {
  const double scale = GetParam();
  for (const auto &c : adversarial_cases(scale, 12)) {
    const TrianglePairDistance r = triangle_distance(c.a, c.b);
    const bool sliver = c.name.find("sliver") != std::string::npos;
    const double tol = (sliver ? 1e-9 : 1e-12) * scale;
    expect_valid(r, c.name);
    EXPECT_EQ(r.intersecting, c.intersecting) << c.name << " at scale " << scale;
    EXPECT_NEAR(r.distance, c.distance, tol) << c.name << " at scale " << scale;
    if (r.intersecting) { // the reported point is in both triangles
      EXPECT_LT(distance_to_triangle(r.point_a, c.a), 1e-9 * scale) << c.name;
      EXPECT_LT(distance_to_triangle(r.point_a, c.b), 1e-9 * scale) << c.name;
      EXPECT_GE(r.penetration_depth, 0.0) << c.name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scales, TriangleDistanceAtScale, ::testing::Values(1e-6, 1e-3, 1.0, 1e3));

TEST(TriangleDistance, SymmetricInItsArguments) {
  for (const auto &c : adversarial_cases(1e-3, 13)) {
    const TrianglePairDistance ab = triangle_distance(c.a, c.b), ba = triangle_distance(c.b, c.a);
    EXPECT_NEAR(ab.distance, ba.distance, 1e-15) << c.name;
    EXPECT_EQ(ab.intersecting, ba.intersecting) << c.name;
    if (!ab.intersecting) {
      EXPECT_NEAR(ab.normal.dot(ba.normal), -1.0, 1e-9) << c.name;
    }
  }
}

TEST(TriangleDistance, NearlyParallelEdgesGiveTheExactDistance) {
  // Unit edges crossing (seen along z) at angle theta, h apart: the distance is exactly h.
  // The edge-edge solve once formed a e - b^2, which loses every digit at small angles
  // (h + 2e-8 at theta 1e-7); found by tests/fuzz (fuzz_triangle_distance).
  for (double theta : {1e-5, 1e-6, 1e-7, 3e-8, 1e-8, 1e-10})
    for (double h : {1e-9, 1e-6}) {
      const Eigen::Vector3d a[3] = {{0, 0, 0}, {1, 0, 0}, {0.5, -1, -0.5}};
      const Eigen::Vector3d b[3] = {{0, -theta / 2, h}, {1, theta / 2, h}, {0.5, 1, h + 0.5}};
      EXPECT_NEAR(triangle_distance(a, b).distance, h, 1e-15) << theta << " " << h;
      EXPECT_NEAR(triangle_distance(b, a).distance, h, 1e-15) << theta << " " << h;
    }
}

TEST(TriangleDistance, SeparatedNormalPointsFromAToB) {
  const Eigen::Vector3d a[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const Eigen::Vector3d b[3] = {{0.2, 0.2, 0.5}, {0.4, 0.2, 1}, {0.2, 0.4, 1}};
  const TrianglePairDistance r = triangle_distance(a, b);
  EXPECT_DOUBLE_EQ(r.distance, 0.5);
  EXPECT_NEAR((r.normal - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
  EXPECT_NEAR((r.point_a - Eigen::Vector3d(0.2, 0.2, 0)).norm(), 0.0, 1e-15);
}

TEST(TriangleDistance, BlockAgreesWithScalarOnEveryLane) {
  std::vector<TriangleCase> cases = adversarial_cases(1.0, 14);
  for (const auto &c : adversarial_cases(1e-6, 15))
    cases.push_back(c);
  for (std::size_t first = 0; first < cases.size(); first += kPairLanes) {
    const int n = static_cast<int>(std::min<std::size_t>(kPairLanes, cases.size() - first));
    TrianglePairBlock block;
    for (int l = 0; l < kPairLanes; ++l) {
      const auto &c = cases[first + std::min(l, n - 1)];
      block.set_lane(l, c.a, c.b);
    }
    TrianglePairDistance out[kPairLanes];
    brute_force_block(block, n, out);
    for (int l = 0; l < n; ++l) {
      const auto &c = cases[first + l];
      const TrianglePairDistance s = triangle_distance(c.a, c.b);
      // Same operations; only FMA contraction may differ between the two compilations.
      const double scale = (c.a[0] - c.b[0]).norm() + c.a[0].norm() + 1e-300;
      EXPECT_NEAR(out[l].distance, s.distance, 1e-14 * scale) << c.name;
      EXPECT_EQ(out[l].intersecting, s.intersecting) << c.name;
    }
  }
}

// The reduction's shortcut for pairs the kernel certified apart: the same distance to rounding
// (by a vertex's height where that is certified, else the same 15 checks) wherever
// triangle_distance finds them separated; negative where it finds them touching.
TEST(TriangleDistance, SeparatedDistanceMatchesTheFullOne) {
  std::vector<TriangleCase> cases = adversarial_cases(1.0, 21);
  for (const auto &c : adversarial_cases(1e-6, 22))
    cases.push_back(c);
  for (const auto &c : adversarial_cases(1e3, 23))
    cases.push_back(c);
  int separated = 0, touching = 0;
  for (const auto &c : cases) {
    const TrianglePairDistance full = triangle_distance(c.a, c.b);
    const double d = separated_triangle_distance(c.a, c.b);
    if (!full.intersecting) {
      EXPECT_NEAR(d, full.distance, 1e-15 * (c.a[0].norm() + c.b[0].norm())) << c.name;
      ++separated;
    } else if (d < 0.0) {
      ++touching; // touching within kTouchRatio: no distance
    } else {
      // crossing edges: not a pair the shortcut is for; its 15 checks see only the edges
      EXPECT_GE(d, 0.0) << c.name;
    }
  }
  EXPECT_GT(separated, 100);
  EXPECT_GT(touching, 0);

  // Nearly parallel faces (the reduction's polygon members), overlapping in projection or
  // beside each other: closest pairs of every kind (a vertex over a face, nearer or not than
  // the rest of its triangle; crossing and parallel edges), at three scales.
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double scale : {1e-6, 1.0, 1e3}) {
    const Eigen::Vector3d far(3.0, -2.0, 5.0); // away from the origin, as particles are
    for (int trial = 0; trial < 20000; ++trial) {
      const Eigen::Vector3d shift(0.8 * u(rng), 0.8 * u(rng), 0.05 + 0.04 * u(rng));
      Eigen::Vector3d a[3], b[3];
      for (int k = 0; k < 3; ++k) {
        a[k] = scale * (far + Eigen::Vector3d(u(rng), u(rng), 0.03 * u(rng)));
        b[k] = scale * (far + shift + Eigen::Vector3d(u(rng), u(rng), 0.03 * u(rng)));
      }
      const TrianglePairDistance full = triangle_distance(a, b);
      if (full.intersecting)
        continue;
      EXPECT_NEAR(separated_triangle_distance(a, b), full.distance, 1e-15 * scale * 10.0)
          << "scale " << scale << " trial " << trial;
    }
  }
}
