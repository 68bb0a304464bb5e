// fit_rigid_motion: exact for the node velocities of rigid motions (rotating drums, sliding
// belts), minimum-norm for collinear nodes, a least-squares fit otherwise.
#include "body/rigid_motion.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>
#include <vector>

using Eigen::Vector3d;

namespace {

struct Nodes {
  std::vector<Vector3d> p, v;
};

// Nodes of a body rotating at omega about an axis through `pivot`, also translating at u.
Nodes rigid(const std::vector<Vector3d> &points, const Vector3d &pivot, const Vector3d &omega,
            const Vector3d &u) {
  Nodes n;
  n.p = points;
  for (const Vector3d &p : points)
    n.v.push_back(u + omega.cross(p - pivot));
  return n;
}

} // namespace

TEST(RigidMotion, RotatingDrumPatchIsExactAwayFromItsNodes) {
  // One triangle of a drum of radius 0.1 m about the y axis at 3 rad/s; the contact point is
  // 5 mm from the nodes' mean, where the mean node velocity would be off by omega x 5 mm.
  const double r = 0.1, w = 3.0;
  std::vector<Vector3d> pts = {{r, 0, 0}, {r * std::cos(0.05), 0.01, r * std::sin(0.05)},
                               {r * std::cos(0.05), -0.01, r * std::sin(0.05)}};
  const Nodes n = rigid(pts, Vector3d::Zero(), Vector3d(0, w, 0), Vector3d::Zero());
  const tri::RigidMotion m = tri::fit_rigid_motion(n.p.data(), n.v.data(), 3);
  const Vector3d at(r * std::cos(0.02), 0.004, r * std::sin(0.02));
  const Vector3d exact = Vector3d(0, w, 0).cross(at);
  const Vector3d fitted = m.velocity + m.omega.cross(at - m.centre);
  EXPECT_LT((fitted - exact).norm(), 1e-13 * w * r);
  EXPECT_LT((m.omega - Vector3d(0, w, 0)).norm(), 1e-12 * w);
  // The mean node velocity misses the rotation about the mean (what the host used before).
  const Vector3d mean = (n.v[0] + n.v[1] + n.v[2]) / 3.0;
  EXPECT_GT((mean - exact).norm(), 1e-3 * w * r);
}

TEST(RigidMotion, RandomRigidMotionsAreRecovered) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double scale = std::pow(10.0, -4 + trial % 6); // 1e-4 .. 10 m
    std::vector<Vector3d> pts;
    const int count = 3 + trial % 20;
    for (int k = 0; k < count; ++k)
      pts.push_back(scale * Vector3d(u(rng), u(rng), u(rng)));
    const Vector3d omega(u(rng), u(rng), u(rng)), vel(u(rng), u(rng), u(rng));
    const Vector3d pivot = scale * Vector3d(u(rng), u(rng), u(rng));
    const Nodes n = rigid(pts, pivot, omega, vel);
    const tri::RigidMotion m = tri::fit_rigid_motion(n.p.data(), n.v.data(), count);
    for (int k = 0; k < count; ++k) {
      const Vector3d fitted = m.velocity + m.omega.cross(n.p[k] - m.centre);
      EXPECT_LT((fitted - n.v[k]).norm(), 1e-11 * (vel.norm() + omega.norm() * scale))
          << "trial " << trial;
    }
  }
}

TEST(RigidMotion, PureTranslationHasNoSpin) {
  std::vector<Vector3d> pts = {{0, 0, 0}, {1e-3, 0, 0}, {0, 1e-3, 0}, {1e-3, 1e-3, 1e-4}};
  const Nodes n = rigid(pts, Vector3d::Zero(), Vector3d::Zero(), Vector3d(0.3, -0.1, 0.2));
  const tri::RigidMotion m = tri::fit_rigid_motion(n.p.data(), n.v.data(), 4);
  EXPECT_LT(m.omega.norm(), 1e-12);
  EXPECT_LT((m.velocity - Vector3d(0.3, -0.1, 0.2)).norm(), 1e-15);
}

TEST(RigidMotion, CollinearNodesGiveTheMinimumNormSpin) {
  // Nodes on the x axis of a body spinning about x (unobservable) and about z (observable).
  std::vector<Vector3d> pts = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const Nodes n = rigid(pts, Vector3d::Zero(), Vector3d(5, 0, 2), Vector3d::Zero());
  const tri::RigidMotion m = tri::fit_rigid_motion(n.p.data(), n.v.data(), 3);
  EXPECT_NEAR(m.omega.x(), 0.0, 1e-12);
  EXPECT_NEAR(m.omega.z(), 2.0, 1e-12);
  for (int k = 0; k < 3; ++k)
    EXPECT_LT((m.velocity + m.omega.cross(n.p[k] - m.centre) - n.v[k]).norm(), 1e-12);
}

TEST(RigidMotion, NoNodesOrOneNode) {
  const tri::RigidMotion none = tri::fit_rigid_motion(nullptr, nullptr, 0);
  EXPECT_EQ(none.velocity.norm(), 0.0);
  const Vector3d p(1, 2, 3), v(4, 5, 6);
  const tri::RigidMotion one = tri::fit_rigid_motion(&p, &v, 1);
  EXPECT_EQ(one.centre, p);
  EXPECT_EQ(one.velocity, v);
  EXPECT_EQ(one.omega.norm(), 0.0);
}
