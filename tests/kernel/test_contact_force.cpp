// Tests of contact_model.h, contact_history.h and contact_force.h: hand-computed LIGGGHTS
// hooke/stiffness forces, the tangential history (stick, slip, projection), no_history
// friction, torques with friction, Newton's third law and angular momentum balance, history
// slot matching, the returned statistics, and no false torque on a cube resting flat.
#include "contact/contact_reduction.h"
#include "distance/particle_contacts.h"
#include "model/contact_force.h"
#include "triangle_contact_search.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

namespace {

using Eigen::Vector3d;
using tri::BodyState;
using tri::ContactCoefficients;
using tri::ContactPoint;

ContactCoefficients material() {
  ContactCoefficients c;
  c.kn = 2000.0;
  c.kt = 1000.0;
  c.gamman = 20.0;
  c.gammat = 10.0;
  c.mu = 0.5;
  return c;
}

ContactPoint point(const Vector3d &p, const Vector3d &n, double overlap) {
  ContactPoint c;
  c.point = p;
  c.normal = n.normalized();
  c.overlap = overlap;
  c.min_distance = 2e-4 - overlap;
  c.num_merged = 3;
  return c;
}

BodyState body(const Vector3d &x, const Vector3d &v, const Vector3d &w, double m) {
  BodyState b;
  b.x = x;
  b.v = v;
  b.omega = w;
  b.mass = m;
  return b;
}

// ---- normal sub-model ----

TEST(NormalForce, SpringAndDampingByHand) {
  ContactCoefficients c = material();
  const double meff = tri::effective_mass(2.0, 3.0); // 1.2 kg
  EXPECT_DOUBLE_EQ(meff, 1.2);
  // Approaching at 0.1 m/s (v_n = -0.1): 2000 * 1e-4 + 20 * 1.2 * 0.1 = 0.2 + 2.4.
  EXPECT_NEAR(tri::normal_force(c, 1e-4, -0.1, meff), 2.6, 1e-12);
  c.gamman = 0.0;
  EXPECT_NEAR(tri::normal_force(c, 1e-4, -0.1, meff), 0.2, 1e-15);
}

TEST(NormalForce, AbsoluteDampingIgnoresMass) {
  ContactCoefficients c = material();
  c.absolute_damping = true; // gamman in kg/s: 0.2 + 20 * 0.1
  EXPECT_NEAR(tri::normal_force(c, 1e-4, -0.1, 1.2), 2.2, 1e-12);
  EXPECT_NEAR(tri::normal_force(c, 1e-4, -0.1, 7.0), 2.2, 1e-12);
}

TEST(NormalForce, LimitForceClampsAttraction) {
  ContactCoefficients c = material();
  // Separating at 1 m/s: 0.2 - 20 * 1.2 * 1 = -23.8 (LIGGGHTS default: attraction allowed).
  EXPECT_NEAR(tri::normal_force(c, 1e-4, 1.0, 1.2), -23.8, 1e-12);
  c.limit_force = true;
  EXPECT_EQ(tri::normal_force(c, 1e-4, 1.0, 1.2), 0.0);
  EXPECT_NEAR(tri::normal_force(c, 1e-4, -0.1, 1.2), 2.6, 1e-12); // repulsion unchanged
}

TEST(NormalForce, WallEffectiveMassIsTheParticleMass) {
  EXPECT_DOUBLE_EQ(tri::effective_mass(2.0, 0.0), 2.0);
  EXPECT_DOUBLE_EQ(tri::effective_mass(2.0, std::numeric_limits<double>::infinity()), 2.0);
  EXPECT_DOUBLE_EQ(tri::effective_mass(0.0, 3.0), 3.0);
}

TEST(Coefficients, ErrorsNameTheCoefficient) {
  ContactCoefficients c = material();
  EXPECT_EQ(tri::coefficient_error(c), "");
  c.mu = -0.1;
  EXPECT_NE(tri::coefficient_error(c).find("coefficientFriction"), std::string::npos);
  c = material();
  c.kn = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(tri::coefficient_error(c).find("kn"), std::string::npos);
}

// ---- tangential sub-models ----

TEST(TangentialHistory, StickIsSpringPlusDamping) {
  const ContactCoefficients c = material();
  const Vector3d n = Vector3d::UnitZ(), vt(0.01, 0, 0);
  Vector3d shear = Vector3d::Zero();
  const double dt = 1e-3, meff = 1.2, fn = 10.0; // cap mu fn = 5 N, not reached
  const Vector3d ft = tri::tangential_force_history(c, n, vt, fn, meff, dt, shear);
  EXPECT_NEAR(shear.x(), 1e-5, 1e-20);
  // -kt shear - gammat meff vt = -0.01 - 10 * 1.2 * 0.01 = -0.13
  EXPECT_NEAR(ft.x(), -0.13, 1e-14);
  EXPECT_EQ(ft.y(), 0.0);
  EXPECT_EQ(ft.z(), 0.0);
  // Second step: the spring keeps growing.
  const Vector3d ft2 = tri::tangential_force_history(c, n, vt, fn, meff, dt, shear);
  EXPECT_NEAR(shear.x(), 2e-5, 1e-20);
  EXPECT_NEAR(ft2.x(), -0.02 - 0.12, 1e-14);
}

TEST(TangentialHistory, NoDampingWhenSwitchedOff) {
  ContactCoefficients c = material();
  c.tangential_damping = false;
  Vector3d shear = Vector3d::Zero();
  const Vector3d ft = tri::tangential_force_history(c, Vector3d::UnitZ(), Vector3d(0.01, 0, 0),
                                                    10.0, 1.2, 1e-3, shear);
  EXPECT_NEAR(ft.x(), -0.01, 1e-15);
}

TEST(TangentialHistory, SlipCapsAtCoulombAndRescalesShear) {
  const ContactCoefficients c = material();
  const Vector3d n = Vector3d::UnitZ();
  Vector3d shear(3e-3, 4e-3, 0); // |kt shear| = 5 N
  const double fn = 2.0;         // cap: 0.5 * 2 = 1 N
  const Vector3d ft = tri::tangential_force_history(c, n, Vector3d::Zero(), fn, 1.2, 1e-3, shear);
  EXPECT_NEAR(ft.norm(), 1.0, 1e-12);
  EXPECT_NEAR(ft.x(), -0.6, 1e-12); // direction of -shear, no damping added while sliding
  EXPECT_NEAR(ft.y(), -0.8, 1e-12);
  EXPECT_NEAR(shear.x(), 0.6 / 1000.0, 1e-15); // shear = -ft / kt
  EXPECT_NEAR(shear.y(), 0.8 / 1000.0, 1e-15);
  // An attractive normal force caps by its magnitude (LIGGGHTS uses |Fn|).
  Vector3d shear2(3e-3, 4e-3, 0);
  EXPECT_NEAR(tri::tangential_force_history(c, n, Vector3d::Zero(), -fn, 1.2, 1e-3, shear2).norm(),
              1.0, 1e-12);
}

// Unlike LIGGGHTS (contact_model.h): when the spring is below the Coulomb limit but spring +
// damping is above it, the total is capped at mu |F_n| in its own direction; the shear stays.
TEST(TangentialHistory, DampedTotalIsCappedAtCoulomb) {
  const ContactCoefficients c = material();
  const Vector3d n = Vector3d::UnitZ();
  Vector3d shear(0, 2e-4, 0);
  const Vector3d vt(0.1, 0, 0);
  const double dt = 1e-3, meff = 1.2, fn = 1.0; // cap 0.5 N
  // shear -> (1e-4, 2e-4): spring (-0.1, -0.2), |.| = 0.224 < 0.5; damping -10 * 1.2 * vt =
  // (-1.2, 0): total (-1.3, -0.2), |.| = 1.315 > 0.5, scaled to 0.5 N.
  const Vector3d ft = tri::tangential_force_history(c, n, vt, fn, meff, dt, shear);
  EXPECT_NEAR(shear.x(), 1e-4, 1e-18);
  EXPECT_NEAR(shear.y(), 2e-4, 1e-18);
  const Vector3d uncapped(-1.3, -0.2, 0);
  EXPECT_NEAR(ft.norm(), 0.5, 1e-14);
  EXPECT_NEAR((ft - 0.5 / uncapped.norm() * uncapped).norm(), 0.0, 1e-14);
  // Below the cap nothing changes (fn = 10: cap 5 N > 1.315 N): LIGGGHTS's value.
  Vector3d shear2(0, 2e-4, 0);
  const Vector3d ft2 = tri::tangential_force_history(c, n, vt, 10.0, meff, dt, shear2);
  EXPECT_NEAR((ft2 - uncapped).norm(), 0.0, 1e-14);
  // mu = 0: no tangential force at all, damping included.
  ContactCoefficients frictionless = c;
  frictionless.mu = 0.0;
  Vector3d shear3 = Vector3d::Zero();
  EXPECT_EQ(tri::tangential_force_history(frictionless, n, vt, 10.0, meff, dt, shear3).norm(),
            0.0);
}

TEST(TangentialHistory, ShearIsProjectedOntoRotatedTangentPlane) {
  ContactCoefficients c = material();
  c.gammat = 0.0;
  Vector3d shear(1e-5, 0, 0); // built up while n was +z
  const double angle = 0.3;   // the normal turned about y
  const Vector3d n(std::sin(angle), 0, std::cos(angle));
  const Vector3d old = shear;
  const Vector3d ft = tri::tangential_force_history(c, n, Vector3d::Zero(), 10.0, 1.2, 1e-3, shear);
  const Vector3d expected = old - old.dot(n) * n;
  EXPECT_NEAR(shear.dot(n), 0.0, 1e-20);
  EXPECT_NEAR((shear - expected).norm(), 0.0, 1e-20);
  EXPECT_NEAR(shear.norm(), 1e-5 * std::cos(angle), 1e-18);
  EXPECT_NEAR((ft + c.kt * expected).norm(), 0.0, 1e-15);
}

TEST(TangentialNoHistory, ViscousBelowCapCoulombAbove) {
  const ContactCoefficients c = material();
  const Vector3d vt(0.0, 0.02, 0.0);
  // Viscous: gammat meff |vt| = 10 * 1.2 * 0.02 = 0.24 N < mu fn = 5 N.
  Vector3d ft = tri::tangential_force_no_history(c, vt, 10.0, 1.2);
  EXPECT_NEAR(ft.y(), -0.24, 1e-14);
  EXPECT_EQ(ft.x(), 0.0);
  // Coulomb: mu fn = 0.5 * 0.2 = 0.1 N < 0.24 N.
  ft = tri::tangential_force_no_history(c, vt, 0.2, 1.2);
  EXPECT_NEAR(ft.y(), -0.1, 1e-15);
  EXPECT_EQ(tri::tangential_force_no_history(c, Vector3d::Zero(), 10.0, 1.2), Vector3d::Zero());
}

// ---- twisting friction of face contacts ----

tri::TwistPatch twist_patch(double lever, double polar_per_area) {
  tri::TwistPatch t;
  t.lever = lever;
  t.polar_per_area = polar_per_area;
  return t;
}

// Without a twist patch the friction is tangential_force_history's / _no_history's, bit for
// bit, and the twist spring is released.
TEST(TwistFriction, PointContactIsTheTangentialModelExactly) {
  const ContactCoefficients c = material();
  const Vector3d n = Vector3d(0.2, -0.3, 1).normalized(), vt(0.01, 0.02, 0.004);
  for (const double fn : {10.0, 0.02}) {
    Vector3d shear_a(1e-4, -2e-4, 0), shear_b = shear_a;
    double twist = 0.3;
    const tri::Friction f =
        tri::friction_history(c, n, vt, 5.0, fn, 1.2, 1e-3, tri::TwistPatch(), shear_a, twist);
    const Vector3d ft = tri::tangential_force_history(c, n, vt, fn, 1.2, 1e-3, shear_b);
    EXPECT_EQ(f.force, ft);
    EXPECT_EQ(shear_a, shear_b);
    EXPECT_EQ(f.twist_torque, 0.0);
    EXPECT_EQ(twist, 0.0);
    EXPECT_EQ(tri::friction_no_history(c, vt, 5.0, fn, 1.2, tri::TwistPatch()).force,
              tri::tangential_force_no_history(c, vt, fn, 1.2));
  }
}

// Sticking: the twist spring is kt tr(J)/A per radian and its damper gammat m_eff tr(J)/A,
// by hand; the torque opposes the relative rotation about n.
TEST(TwistFriction, TwistSpringAndDamperByHand) {
  ContactCoefficients c = material(); // kt 1000, gammat 10, mu 0.5
  const Vector3d n = Vector3d::UnitZ();
  const double ppa = 2e-6, lever = 1.5e-3, meff = 1.2, dt = 1e-3, fn = 10.0; // T_max 7.5e-3 N m
  Vector3d shear = Vector3d::Zero();
  double twist = 0.0;
  const double w = 0.2; // rad/s
  tri::Friction f =
      tri::friction_history(c, n, Vector3d::Zero(), w, fn, meff, dt, twist_patch(lever, ppa), shear,
                            twist);
  EXPECT_NEAR(twist, 2e-4, 1e-18);
  // -kt ppa twist - gammat meff ppa w = -1000 * 2e-6 * 2e-4 - 10 * 1.2 * 2e-6 * 0.2
  EXPECT_NEAR(f.twist_torque, -4e-7 - 4.8e-6, 1e-20);
  EXPECT_EQ(f.force, Vector3d::Zero());
  c.tangential_damping = false;
  f = tri::friction_history(c, n, Vector3d::Zero(), w, fn, meff, dt, twist_patch(lever, ppa), shear,
                            twist);
  EXPECT_NEAR(twist, 4e-4, 1e-18);
  EXPECT_NEAR(f.twist_torque, -8e-7, 1e-20);
  // The opposite rotation unwinds it.
  f = tri::friction_history(c, n, Vector3d::Zero(), -2 * w, fn, meff, dt, twist_patch(lever, ppa),
                            shear, twist);
  EXPECT_NEAR(twist, 0.0, 1e-18);
}

// Slipping in pure twist: the torque is mu |F_n| lever (Coulomb friction spread over the patch)
// and the spring is held there; sliding alone gives mu |F_n|, as before.
TEST(TwistFriction, PureTwistSlipsAtMuFnTimesTheMeanRadius) {
  const ContactCoefficients c = material();
  const Vector3d n = Vector3d::UnitZ();
  const double ppa = 2e-6, lever = 1.5e-3, fn = 2.0; // T_max = 0.5 * 2 * 1.5e-3 = 1.5e-3 N m
  Vector3d shear = Vector3d::Zero();
  double twist = 3.0; // spring -6e-3 N m: beyond the limit
  tri::Friction f = tri::friction_history(c, n, Vector3d::Zero(), 0.0, fn, 1.2, 1e-3,
                                          twist_patch(lever, ppa), shear, twist);
  EXPECT_NEAR(f.twist_torque, -1.5e-3, 1e-17);
  EXPECT_NEAR(twist, 1.5e-3 / (c.kt * ppa), 1e-14);
  EXPECT_EQ(f.force, Vector3d::Zero());
  // Attractive normal force: |F_n|.
  twist = -3.0;
  f = tri::friction_history(c, n, Vector3d::Zero(), 0.0, -fn, 1.2, 1e-3, twist_patch(lever, ppa),
                            shear, twist);
  EXPECT_NEAR(f.twist_torque, 1.5e-3, 1e-17);
  // Pure sliding with a twist patch: the Coulomb cap of tangential_force_history.
  shear = Vector3d(3e-3, 4e-3, 0);
  twist = 0.0;
  f = tri::friction_history(c, n, Vector3d::Zero(), 0.0, fn, 1.2, 1e-3, twist_patch(lever, ppa),
                            shear, twist);
  EXPECT_NEAR((f.force - Vector3d(-0.6, -0.8, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((shear - Vector3d(0.6e-3, 0.8e-3, 0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(f.twist_torque, 0.0);
  // mu = 0: nothing, both springs released.
  ContactCoefficients frictionless = c;
  frictionless.mu = 0.0;
  twist = 1.0;
  f = tri::friction_history(frictionless, n, Vector3d(0.1, 0, 0), 1.0, fn, 1.2, 1e-3,
                            twist_patch(lever, ppa), shear, twist);
  EXPECT_EQ(f.force, Vector3d::Zero());
  EXPECT_EQ(f.twist_torque, 0.0);
  EXPECT_EQ(twist, 0.0);
}

// Sliding and twisting share one budget: the springs are returned radially onto the ellipse
// (|F| / F_max)^2 + (T / T_max)^2 = 1; the damped total is scaled onto it likewise with the
// springs unchanged; no_history scales its viscous pair onto it.
TEST(TwistFriction, SlidingAndTwistingShareTheEllipse) {
  ContactCoefficients c = material();
  const Vector3d n = Vector3d::UnitZ();
  const double ppa = 2e-6, lever = 1.5e-3, fn = 2.0, fmax = 1.0, tmax = 1.5e-3;
  // Springs at (3, 4) of their limits in the two directions: s = 5.
  Vector3d shear(3.0 * fmax / c.kt, 0, 0);
  double twist = -4.0 * tmax / (c.kt * ppa);
  tri::Friction f = tri::friction_history(c, n, Vector3d::Zero(), 0.0, fn, 1.2, 1e-3,
                                          twist_patch(lever, ppa), shear, twist);
  EXPECT_NEAR(f.force.x(), -0.6 * fmax, 1e-14);
  EXPECT_NEAR(f.twist_torque, 0.8 * tmax, 1e-17);
  EXPECT_NEAR(std::hypot(f.force.norm() / fmax, f.twist_torque / tmax), 1.0, 1e-14);
  EXPECT_NEAR(shear.x(), 0.6 * fmax / c.kt, 1e-17);
  EXPECT_NEAR(twist, -0.8 * tmax / (c.kt * ppa), 1e-13);
  // Inside the ellipse by the springs, outside with the dampers: scaled, springs kept.
  shear = Vector3d(0.3 * fmax / c.kt, 0, 0);
  twist = 0.0;
  const Vector3d vt(0.05, 0, 0);
  const double w = 100.0, meff = 1.2, dt = 1e-6;
  const Vector3d shear_after = shear + vt * dt;
  const double twist_after = w * dt;
  f = tri::friction_history(c, n, vt, w, fn, meff, dt, twist_patch(lever, ppa), shear, twist);
  const Vector3d f_raw = -c.kt * shear_after - c.gammat * meff * vt;
  const double t_raw = -c.kt * ppa * twist_after - c.gammat * meff * ppa * w;
  const double s = std::hypot(f_raw.norm() / fmax, t_raw / tmax);
  ASSERT_GT(s, 1.0);
  EXPECT_NEAR((f.force - f_raw / s).norm(), 0.0, 1e-14);
  EXPECT_NEAR(f.twist_torque, t_raw / s, 1e-17);
  EXPECT_NEAR((shear - shear_after).norm(), 0.0, 1e-20);
  EXPECT_NEAR(twist, twist_after, 1e-20);
  // no_history: viscous in both, scaled onto the ellipse when outside it.
  const tri::Friction v = tri::friction_no_history(c, vt, w, fn, meff, twist_patch(lever, ppa));
  const Vector3d fv = -c.gammat * meff * vt;
  const double tv = -c.gammat * meff * ppa * w;
  const double sv = std::hypot(fv.norm() / fmax, tv / tmax);
  ASSERT_GT(sv, 1.0);
  EXPECT_NEAR((v.force - fv / sv).norm(), 0.0, 1e-14);
  EXPECT_NEAR(v.twist_torque, tv / sv, 1e-17);
  const tri::Friction slow =
      tri::friction_no_history(c, 1e-3 * vt, 1e-3 * w, fn, meff, twist_patch(lever, ppa));
  EXPECT_NEAR(slow.twist_torque, 1e-3 * tv, 1e-20);
}

// ---- rocking damper of face contacts ----

// A square patch of side L (J = L^4/12 diag(1, 1, 0)) and an L x W rectangle: the couple on b
// is -(gamma_n / A) (trace(J) P - J) w, by hand: about x it is -gamma_n W^2 / 12 w_x (rotation
// about x moves the patch along n in proportion to y, whose extent is W), about y
// -gamma_n L^2 / 12 w_y; twisting about n is not resisted; it opposes the relative rotation.
TEST(RockingCouple, ValueAndSignByHand) {
  ContactCoefficients c = material(); // gamman 20 1/s, meff 1.2 kg: gamma_n = 24 kg/s
  const double meff = 1.2, gamma = 24.0, L = 2e-3, W = 0.5e-3;
  const Vector3d n = Vector3d::UnitZ();
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  J(0, 0) = W * L * L * L / 12; // integral x^2 dA
  J(1, 1) = L * W * W * W / 12; // integral y^2 dA
  const Vector3d w(3.0, -2.0, 7.0);
  const Vector3d tau = tri::rocking_couple(c, n, L * W, J, w, 10.0, meff);
  EXPECT_NEAR(tau.x(), -gamma * W * W / 12 * w.x(), 1e-15);
  EXPECT_NEAR(tau.y(), -gamma * L * L / 12 * w.y(), 1e-15);
  EXPECT_EQ(tau.z(), 0.0);
  EXPECT_LT(tau.dot(w), 0.0); // dissipative
  // Absolute damping: gamman in kg/s, the mass does not enter.
  c.absolute_damping = true;
  EXPECT_NEAR(tri::rocking_couple(c, n, L * W, J, w, 10.0, 7.0).y(), -20.0 * L * L / 12 * w.y(),
              1e-15);
  c.absolute_damping = false;
  // No patch or no damping: nothing.
  EXPECT_EQ(tri::rocking_couple(c, n, 0.0, J, w, 10.0, meff), Vector3d::Zero());
  c.gamman = 0.0;
  EXPECT_EQ(tri::rocking_couple(c, n, L * W, J, w, 10.0, meff), Vector3d::Zero());
}

// With limit_force the couple is at most |F_n| sqrt(2 trace(J) / A) (the lever of a disk).
TEST(RockingCouple, CappedByTheNormalForceWithLimitForce) {
  ContactCoefficients c = material();
  const double L = 2e-3, fn = 1e-3;
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  J(0, 0) = J(1, 1) = L * L * L * L / 12;
  const Vector3d w(0, 500.0, 0); // uncapped: 24 * L^2 / 12 * 500 = 4e-3 N m
  const Vector3d free = tri::rocking_couple(c, Vector3d::UnitZ(), L * L, J, w, fn, 1.2);
  EXPECT_NEAR(free.y(), -4e-3, 1e-15);
  c.limit_force = true;
  const Vector3d capped = tri::rocking_couple(c, Vector3d::UnitZ(), L * L, J, w, fn, 1.2);
  EXPECT_NEAR(capped.y(), -fn * std::sqrt(2 * (L * L / 6)), 1e-18);
  EXPECT_EQ(capped.x(), 0.0);
  EXPECT_EQ(tri::rocking_couple(c, Vector3d::UnitZ(), L * L, J, w, 0.0, 1.2), Vector3d::Zero());
}

// The tensor formula against the dashpot it stands for: a triangle-shaped patch in a tilted
// plane, about a point off its centroid, integrated on a fine grid:
// tau_b = -(gamma_n / A) sum over cells of r x n ((w x r) . n) dA.
TEST(RockingCouple, EqualsADashpotSpreadOverThePatch) {
  const ContactCoefficients c = material();
  const double meff = 0.3, gamma = c.gamman * meff;
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.8, Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Vector3d n = R.col(2), e1 = R.col(0), e2 = R.col(1);
  const Vector3d p(0.1e-3, -0.05e-3, 0); // in-plane coordinates of the contact point
  // Triangle (0,0), (2,0), (0.5,1.5) mm in (e1, e2).
  const Eigen::Vector2d v0(0, 0), v1(2e-3, 0), v2(0.5e-3, 1.5e-3);
  const int N = 1500;
  double A = 0;
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  Vector3d tau = Vector3d::Zero();
  const Vector3d w(40.0, -25.0, 60.0);
  std::vector<std::pair<Vector3d, double>> cells;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      const Eigen::Vector2d x(2e-3 * (i + 0.5) / N, 1.5e-3 * (j + 0.5) / N);
      auto side = [&](const Eigen::Vector2d &a, const Eigen::Vector2d &b) {
        return (b - a).x() * (x - a).y() - (b - a).y() * (x - a).x();
      };
      if (side(v0, v1) < 0 || side(v1, v2) < 0 || side(v2, v0) < 0)
        continue;
      const double dA = (2e-3 / N) * (1.5e-3 / N);
      const Vector3d r = (x.x() - p.x()) * e1 + (x.y() - p.y()) * e2;
      A += dA;
      J += dA * r * r.transpose();
      cells.push_back({r, dA});
    }
  for (const auto &cell : cells)
    tau -= gamma / A * cell.first.cross(n) * (w.cross(cell.first).dot(n) * cell.second);
  const Vector3d got = tri::rocking_couple(c, n, A, J, w, 1.0, meff);
  EXPECT_LE((got - tau).norm(), 1e-12 * tau.norm()) << got.transpose() << " vs "
                                                     << tau.transpose();
  EXPECT_NEAR(got.dot(n), 0.0, 1e-12 * tau.norm());
}

// The result's elastic_energy (compute tri/stats): 1/2 kn energy_overlap^2 summed over the
// points, whatever the damping, friction or force point; none for a pair apart.
TEST(PairContactForce, ElasticEnergyIsTheSpringsPotential) {
  ContactCoefficients c = material();
  const BodyState a = body(Vector3d(0, 0, 0), Vector3d(0.1, 0, 0), Vector3d(0, 0, 30), 1e-3);
  const BodyState b = body(Vector3d(0.004, 0, 0), Vector3d(-0.1, 0, 0), Vector3d(5, 0, 0), 2e-3);
  ContactPoint p = point(Vector3d(0.002, 0, 0), Vector3d(1, 0, 0), 3e-5);
  p.energy_overlap = 3e-5; // a point contact: the overlap itself
  ContactPoint q = point(Vector3d(0.002, 0.001, 0), Vector3d(1, 0.1, 0).normalized(), 1e-5);
  q.energy_overlap = 1.2e-5; // a flat patch: sqrt(Omega) differs from the force's overlap
  const auto r = tri::pair_contact_force({p, q}, a, b, c, 1e-5, nullptr);
  const double expected = 0.5 * c.kn * (3e-5 * 3e-5 + 1.2e-5 * 1.2e-5);
  EXPECT_NEAR(r.elastic_energy, expected, 1e-15 * expected);
  EXPECT_EQ(tri::pair_contact_force({}, a, b, c, 1e-5, nullptr).elastic_energy, 0.0);
}

// In pair_contact_force the couple is pure: the force is that of the same points without a
// patch, torque_b changes by C and torque_a by -C, and the total angular momentum balance holds
// about any point; the relative rotation loses energy.
// The dashpot of a patch (contact_force.h): measured and applied at the patch's area centre,
// the spring at the point. By hand: spring kn overlap n at p, damper -gamma m_eff v_n(c_A) n at
// c_A; its power is -gamma m_eff v_n(c_A)^2 (never positive) and momentum is conserved.
TEST(PairContactForce, PatchDashpotActsAtTheAreaCentre) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto rv = [&](double s) -> Vector3d { return Vector3d(u(rng), u(rng), u(rng)) * s; };
  for (int trial = 0; trial < 20; ++trial) {
    ContactCoefficients c = material();
    c.mu = 0.0; // the normal force alone
    c.limit_force = false;
    const BodyState a = body(rv(0.003), rv(0.1), rv(50.0), 1e-3);
    const BodyState b = body(rv(0.003), rv(0.1), rv(50.0), 2e-3);
    ContactPoint q = point(rv(0.002), rv(1.0), 2e-5);
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - q.normal * q.normal.transpose();
    q.patch_area = 1e-6;
    q.patch_second_moment = 1e-14 * P; // any; face weight 0: no couple
    q.damping_point = q.point + P * rv(5e-4);
    const auto r = tri::pair_contact_force({q}, a, b, c, 1e-5, nullptr);
    const double m_eff = tri::effective_mass(a.mass, b.mass);
    const double v_n =
        tri::contact_kinematics(q.damping_point, q.normal, a, b).v_n; // at c_A
    const Vector3d spring = c.kn * q.overlap * q.normal, damper = -c.gamman * m_eff * v_n * q.normal;
    const double scale = spring.norm() + damper.norm();
    EXPECT_NEAR((r.force_a + spring + damper).norm(), 0.0, 1e-14 * scale);
    const Vector3d torque_b = (q.point - b.x).cross(spring) + (q.damping_point - b.x).cross(damper);
    EXPECT_NEAR((r.torque_b - torque_b).norm(), 0.0, 1e-14 * scale * 0.01);
    // the damper's power on the two bodies: its force times the relative velocity at c_A
    EXPECT_LE(damper.dot(q.normal) * v_n, 0.0);
    const Vector3d total = a.x.cross(r.force_a) + r.torque_a - b.x.cross(r.force_a) + r.torque_b;
    EXPECT_NEAR(total.norm(), 0.0, 1e-13 * scale * 0.01);
  }
}

// The rocking couple scales with the face weight (contact_reduction.h step 6): none for a
// point-like patch (a ball on facets), half at w = 1/2.
TEST(PairContactForce, RockingCoupleScalesWithTheFaceWeight) {
  ContactCoefficients c = material();
  c.mu = 0.0; // no friction, no twist: the couple alone changes with the weight
  const BodyState a = body(Vector3d(0, 0, 0.002), Vector3d::Zero(), Vector3d(30, -20, 0), 1e-3);
  const BodyState wall = body(Vector3d::Zero(), Vector3d::Zero(), Vector3d::Zero(), 0.0);
  ContactPoint q = point(Vector3d(0, 0, 0), Vector3d(0, 0, -1), 2e-5);
  q.patch_area = 4e-6;
  q.patch_second_moment = Eigen::Vector3d(4e-12, 4e-12, 0).asDiagonal();
  q.damping_point = q.point;
  Vector3d torque[3];
  const double weights[3] = {0.0, 0.5, 1.0};
  for (int k = 0; k < 3; ++k) {
    q.face_weight = weights[k];
    torque[k] = tri::pair_contact_force({q}, a, wall, c, 1e-5, nullptr).torque_a;
  }
  const Vector3d couple = torque[2] - torque[0];
  EXPECT_GT(couple.norm(), 0.0);
  EXPECT_NEAR((torque[1] - torque[0] - 0.5 * couple).norm(), 0.0, 1e-14 * couple.norm());
  EXPECT_LT(couple.dot(a.omega), 0.0); // it brakes the rocking
}

TEST(PairContactForce, RockingCoupleIsAPureDissipativeCouple) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto rv = [&](double s) -> Vector3d { return Vector3d(u(rng), u(rng), u(rng)) * s; };
  for (const bool wall : {false, true})
    for (int trial = 0; trial < 20; ++trial) {
      ContactCoefficients c = material();
      c.limit_force = trial % 2 == 1;
      const BodyState a = body(rv(0.003), rv(0.1), rv(50.0), 1e-3);
      const BodyState b = body(rv(0.003), rv(0.1), wall ? Vector3d::Zero() : rv(50.0),
                               wall ? 0.0 : 2e-3);
      std::vector<ContactPoint> plain, patched;
      for (int i = 0; i < 3; ++i) {
        plain.push_back(point(rv(0.002), rv(1.0), 1e-5 * (3 - i)));
        ContactPoint q = plain.back();
        const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - q.normal * q.normal.transpose();
        const Vector3d t1 = P * rv(1e-3), t2 = P * rv(1e-3);
        q.patch_area = 2e-6;
        q.patch_second_moment = 1e-6 / 12 * (t1 * t1.transpose() + t2 * t2.transpose());
        q.face_weight = 1.0;     // a face lying flat: the full couple
        q.damping_point = q.point; // the dashpot where the plain contact has it
        patched.push_back(q);
      }
      double h0[tri::kHistoryDoubles] = {}, h1[tri::kHistoryDoubles] = {};
      const auto r0 = tri::pair_contact_force(plain, a, b, c, 1e-5, h0);
      const auto r1 = tri::pair_contact_force(patched, a, b, c, 1e-5, h1);
      // A patch's spring and dashpot are added separately (the dashpot acts at the area
      // centre, here the point): the same force to rounding.
      EXPECT_NEAR((r1.force_a - r0.force_a).norm(), 0.0, 1e-14 * r0.force_a.norm());
      const Vector3d couple_b = r1.torque_b - r0.torque_b;
      EXPECT_GT(couple_b.norm(), 0.0);
      EXPECT_NEAR((r1.torque_a - r0.torque_a + couple_b).norm(), 0.0,
                  1e-14 * (r0.torque_a.norm() + couple_b.norm()));
      EXPECT_LE(couple_b.dot(b.omega - a.omega), 0.0);
      for (const Vector3d &o : {Vector3d(Vector3d::Zero()), rv(1.0)}) {
        const Vector3d total =
            (a.x - o).cross(r1.force_a) + r1.torque_a - (b.x - o).cross(r1.force_a) + r1.torque_b;
        const double scale = r1.force_a.norm() * (0.01 + o.norm()) + couple_b.norm();
        EXPECT_NEAR(total.norm(), 0.0, 1e-13 * scale);
      }
      for (int k = 0; k < tri::kHistoryDoubles; ++k)
        EXPECT_EQ(h0[k], h1[k]); // the couple does not touch the tangential history
    }
}

// ---- kinematics ----

TEST(ContactKinematics, RelativeVelocityIncludesRotation) {
  const BodyState a = body(Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 0, 2), 1.0);
  const BodyState b = body(Vector3d(0, 0, 1), Vector3d(0, 1, -3), Vector3d(5, 0, 0), 1.0);
  const Vector3d p(0.5, 0, 0.5), n(0, 0, 1);
  const auto k = tri::contact_kinematics(p, n, a, b);
  // v_a(p) = (1,0,0) + (0,0,2) x (0.5,0,0.5) = (1, 1, 0)
  // v_b(p) = (0,1,-3) + (5,0,0) x (0.5,0,-0.5) = (0, 1 + 2.5, -3)
  EXPECT_NEAR((k.v_rel - Vector3d(-1, 2.5, -3)).norm(), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(k.v_n, -3.0); // approaching: negative
  EXPECT_NEAR((k.v_t - Vector3d(-1, 2.5, 0)).norm(), 0.0, 1e-15);
}

// ---- pair force ----

TEST(PairContactForce, NormalForceDirectionAndStaticValue) {
  ContactCoefficients c = material();
  const BodyState a = body(Vector3d(0, 0, 0.003), Vector3d::Zero(), Vector3d::Zero(), 1e-3);
  const BodyState b = body(Vector3d(0, 0, -0.003), Vector3d::Zero(), Vector3d::Zero(), 1e-3);
  double history[tri::kHistoryDoubles] = {};
  // a above b: normal from a to b is -z; a is pushed up by kn overlap = 0.2 N.
  const auto r = tri::pair_contact_force({point(Vector3d::Zero(), -Vector3d::UnitZ(), 1e-4)}, a, b,
                                         c, 1e-6, history);
  EXPECT_NEAR((r.force_a - Vector3d(0, 0, 0.2)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(r.torque_a.norm(), 0.0, 1e-18);
}

TEST(PairContactForce, TorqueIsLeverCrossForceIncludingFriction) {
  ContactCoefficients c = material();
  const BodyState a = body(Vector3d(0, 0, 0.002), Vector3d(0.05, 0, 0), Vector3d(0, 3, 0), 2e-3);
  const BodyState b =
      body(Vector3d(0.001, 0, -0.002), Vector3d(0, 0.01, 0), Vector3d(1, 0, 0), 1e-3);
  const ContactPoint cp = point(Vector3d(0.0005, 0.0002, 0), -Vector3d::UnitZ(), 1e-4);
  double history[tri::kHistoryDoubles] = {};
  const auto r = tri::pair_contact_force({cp}, a, b, c, 1e-5, history);
  // Rebuild the force on b from the sub-models by hand.
  const auto k = tri::contact_kinematics(cp.point, cp.normal, a, b);
  const double meff = tri::effective_mass(a.mass, b.mass);
  const double fn = tri::normal_force(c, cp.overlap, k.v_n, meff);
  Vector3d shear = Vector3d::Zero();
  const Vector3d ft = tri::tangential_force_history(c, cp.normal, k.v_t, fn, meff, 1e-5, shear);
  ASSERT_GT(ft.norm(), 1e-3 * fn); // friction matters in this case
  const Vector3d fb = fn * cp.normal + ft;
  EXPECT_NEAR((r.force_a + fb).norm(), 0.0, 1e-15);
  EXPECT_NEAR((r.torque_a - (cp.point - a.x).cross(-fb)).norm(), 0.0, 1e-18);
  EXPECT_NEAR((r.torque_b - (cp.point - b.x).cross(fb)).norm(), 0.0, 1e-18);
  // Without the friction part the torque differs: friction enters the torque.
  EXPECT_GT((r.torque_a - (cp.point - a.x).cross(-fn * cp.normal)).norm(), 1e-9);
  // The history slot now holds this contact's normal, shear and lever.
  EXPECT_NEAR((tri::slot_normal(history, 0) - cp.normal).norm(), 0.0, 1e-15);
  EXPECT_NEAR((tri::slot_shear(history, 0) - shear).norm(), 0.0, 1e-20);
  // Lever from the midpoint of the centres: unchanged when the host swaps a and b.
  EXPECT_NEAR((tri::slot_lever(history, 0) - (cp.point - 0.5 * (a.x + b.x))).norm(), 0.0, 1e-18);
}

TEST(PairContactForce, HistoryIsTheSameWhenTheHostSwapsTheBodies) {
  // LIGGGHTS keeps a pair's history on both atoms and may present the pair as (j, i) after a
  // neighbour-list rebuild, negating the values marked by history_flips_sign.
  ContactCoefficients c = material();
  const BodyState a = body(Vector3d(0, 0, 0.002), Vector3d(0.05, 0, 0), Vector3d(0, 3, 0), 2e-3);
  const BodyState b =
      body(Vector3d(0.001, 0, -0.002), Vector3d(0, 0.01, 0), Vector3d(1, 0, 0), 1e-3);
  ContactPoint ab = point(Vector3d(0.0005, 0.0002, 0), -Vector3d::UnitZ(), 1e-4);
  ContactPoint ba = ab;
  ba.normal = -ab.normal;
  double h_ab[tri::kHistoryDoubles] = {}, h_ba[tri::kHistoryDoubles] = {};
  for (int step = 0; step < 3; ++step) {
    const auto r_ab = tri::pair_contact_force({ab}, a, b, c, 1e-5, h_ab);
    const auto r_ba = tri::pair_contact_force({ba}, b, a, c, 1e-5, h_ba);
    EXPECT_NEAR((r_ab.force_a + r_ba.force_a).norm(), 0.0, 1e-15 * r_ab.force_a.norm());
    for (int k = 0; k < tri::kHistoryDoubles; ++k) {
      const double swapped = tri::history_flips_sign(k) ? -h_ba[k] : h_ba[k];
      EXPECT_NEAR(h_ab[k], swapped, 1e-15) << "history value " << k << " at step " << step;
    }
  }
}

// A face-like contact: a square patch of side L about the point, in the plane orthogonal to n.
ContactPoint face_point(const Vector3d &p, const Vector3d &n, double overlap, double L,
                        double face_weight = 1.0) {
  ContactPoint c = point(p, n, overlap);
  const Vector3d nn = c.normal;
  c.patch_area = L * L;
  c.patch_second_moment =
      (L * L * L * L / 12.0) * (Eigen::Matrix3d::Identity() - nn * nn.transpose());
  c.patch_mean_radius = L * (std::sqrt(2.0) + std::asinh(1.0)) / 6.0;
  c.face_weight = face_weight;
  return c;
}

// The twist angle is the same seen from either body (history_flips_sign is false for it): the
// host's swapped pair gives the mirrored torques and the same stored twist, sticking and
// slipping.
TEST(PairContactForce, TwistHistoryIsTheSameWhenTheHostSwapsTheBodies) {
  ContactCoefficients c = material();
  const Vector3d n = Vector3d(0.1, -0.2, -1).normalized();
  const BodyState a = body(Vector3d(0, 0, 0.002), Vector3d(0.001, 0, 0), 2.0 * n, 2e-3);
  const BodyState b = body(Vector3d(0.0002, 0, -0.002), Vector3d::Zero(), -1.0 * n, 1e-3);
  for (const double overlap : {1e-4, 1e-7}) { // sticking, then (tiny normal force) slipping
    ContactPoint ab = face_point(Vector3d(0.0001, 0.0002, 0), n, overlap, 0.004);
    ContactPoint ba = ab;
    ba.normal = -ab.normal;
    double h_ab[tri::kHistoryDoubles] = {}, h_ba[tri::kHistoryDoubles] = {};
    for (int step = 0; step < 3; ++step) {
      const auto r_ab = tri::pair_contact_force({ab}, a, b, c, 1e-5, h_ab);
      const auto r_ba = tri::pair_contact_force({ba}, b, a, c, 1e-5, h_ba);
      EXPECT_NEAR((r_ab.force_a + r_ba.force_a).norm(), 0.0, 1e-15 * r_ab.force_a.norm());
      EXPECT_NEAR((r_ab.torque_a - r_ba.torque_b).norm(), 0.0, 1e-15 * r_ab.torque_a.norm());
      EXPECT_NEAR((r_ab.torque_b - r_ba.torque_a).norm(), 0.0, 1e-15 * r_ab.torque_b.norm());
      for (int k = 0; k < tri::kHistoryDoubles; ++k) {
        const double swapped = tri::history_flips_sign(k) ? -h_ba[k] : h_ba[k];
        EXPECT_NEAR(h_ab[k], swapped, 1e-15) << "history value " << k << " at step " << step;
      }
      // b turns by -3 rad/s about n relative to a: the twist is -3 dt per step (or held at the
      // slip limit), negative seen from both sides, and the couple on b about n opposes it.
      EXPECT_LT(tri::slot_twist(h_ab, 0), 0.0);
      EXPECT_EQ(tri::slot_twist(h_ab, 0), tri::slot_twist(h_ba, 0));
      if (overlap == 1e-4) {
        EXPECT_NEAR(tri::slot_twist(h_ab, 0), -3e-5 * (step + 1), 1e-18);
      }
    }
    EXPECT_FALSE(tri::history_flips_sign(9));
    EXPECT_TRUE(tri::history_flips_sign(tri::kHistorySlotDoubles + 5));
  }
}

// A face lying flat, spinning about its normal against a fixed wall and slipping: the contact
// point does not move (v_t = 0 at the centre of rotation), the torque on the spinning body
// about n is mu F_n r_mean against the spin, and there is no force beyond the normal one. A
// point-like contact (face weight 0) of the same patch does not resist the spin at all; half a
// face weight halves the lever.
TEST(PairContactForce, SpinningFaceBrakesAtMuFnTimesTheMeanRadius) {
  ContactCoefficients c = material();
  c.gamman = 0.0;
  const double L = 0.004, overlap = 1e-5;
  const BodyState cube = body(Vector3d(0, 0, 0.002), Vector3d::Zero(), Vector3d(0, 0, 20), 1.6e-4);
  const BodyState wall = body(Vector3d(0, 0, -1), Vector3d::Zero(), Vector3d::Zero(), 0.0);
  for (const double weight : {1.0, 0.5, 0.0}) {
    const ContactPoint p = face_point(Vector3d::Zero(), -Vector3d::UnitZ(), overlap, L, weight);
    double history[tri::kHistoryDoubles] = {};
    tri::PairForceResult r;
    for (int step = 0; step < 200; ++step)
      r = tri::pair_contact_force({p}, cube, wall, c, 1e-5, history);
    const double fn = c.kn * overlap;
    EXPECT_NEAR((r.force_a - Vector3d(0, 0, fn)).norm(), 0.0, 1e-15 * fn);
    const double want = -weight * c.mu * fn * p.patch_mean_radius;
    EXPECT_NEAR(r.torque_a.z(), want, 1e-12 * c.mu * fn * L) << "face weight " << weight;
    EXPECT_NEAR(r.torque_a.head<2>().norm(), 0.0, 1e-15 * fn * L);
  }
}

TEST(PairContactForce, NewtonThirdLawAndAngularMomentumBalance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto rv = [&](double s) -> Vector3d { return Vector3d(u(rng), u(rng), u(rng)) * s; };
  for (const auto model : {tri::TangentialModel::history, tri::TangentialModel::no_history})
    for (int trial = 0; trial < 20; ++trial) {
      ContactCoefficients c = material();
      c.tangential = model;
      const BodyState a = body(rv(0.003), rv(0.1), rv(10.0), 1e-3);
      const BodyState b = body(rv(0.003), rv(0.1), rv(10.0), 2e-3);
      std::vector<ContactPoint> pts;
      for (int i = 0; i < 6; ++i) // more than the history slots on purpose; some face-like
        pts.push_back(i % 2 ? point(rv(0.002), rv(1.0), 1e-5 * (6 - i))
                            : face_point(rv(0.002), rv(1.0), 1e-5 * (6 - i), 0.002, 0.5 + 0.1 * i));
      double history[tri::kHistoryDoubles] = {};
      for (int step = 0; step < 3; ++step) {
        const auto r = tri::pair_contact_force(pts, a, b, c, 1e-5, history);
        const Vector3d force_b = -r.force_a;
        for (const Vector3d &o : {Vector3d(Vector3d::Zero()), rv(1.0)}) {
          const Vector3d total =
              (a.x - o).cross(r.force_a) + r.torque_a + (b.x - o).cross(force_b) + r.torque_b;
          const double scale = r.force_a.norm() * (0.01 + o.norm());
          EXPECT_NEAR(total.norm(), 0.0, 1e-13 * scale);
        }
      }
    }
}

// Patches keep their shear when they swap places in the list, and a patch that appears next to
// them with the same normal starts from zero (matched by lever, not by order).
TEST(PairContactForce, HistoryFollowsPatchesByNormalAndPosition) {
  ContactCoefficients c = material();
  c.gammat = 0.0;
  const BodyState a = body(Vector3d(0, 0, 0.002), Vector3d::Zero(), Vector3d::Zero(), 1e-3);
  BodyState b = body(Vector3d(0, 0, -0.002), Vector3d(0.01, 0, 0), Vector3d::Zero(), 1e-3);
  const Vector3d down = -Vector3d::UnitZ();
  const ContactPoint left = point(Vector3d(-0.001, 0, 0), down, 1e-4);
  const ContactPoint right = point(Vector3d(0.001, 0, 0), down, 5e-5);
  const ContactPoint side = point(Vector3d(0.0015, 0, 0.001), Vector3d::UnitX(), 5e-5);
  double history[tri::kHistoryDoubles] = {};
  const double dt = 1e-4;
  tri::pair_contact_force({left, right}, a, b, c, dt, history); // both gain 1e-6 shear
  b.v = Vector3d::Zero();
  // Reordered, a perpendicular patch appears, the left patch moved a little.
  ContactPoint left2 = left;
  left2.point += Vector3d(2e-5, 0, 0);
  left2.normal = Vector3d(0.01, 0, -1).normalized();
  double after[tri::kHistoryDoubles];
  std::copy(history, history + tri::kHistoryDoubles, after);
  const auto r = tri::pair_contact_force({side, right, left2}, a, b, c, dt, after);
  EXPECT_EQ(r.contacts_after, 3);
  // Slot k = contact k after the call.
  EXPECT_NEAR(tri::slot_shear(after, 0).norm(), 0.0, 1e-20); // side: new
  EXPECT_NEAR(tri::slot_shear(after, 1).x(), 1e-6, 1e-18);   // right kept its shear
  EXPECT_NEAR(tri::slot_shear(after, 2).norm(), 1e-6, 1e-8); // left kept it (re-projected)
  EXPECT_FALSE(tri::slot_occupied(after, 3));
  // The left patch vanishes: its slot is dropped, the others persist.
  double later[tri::kHistoryDoubles];
  std::copy(after, after + tri::kHistoryDoubles, later);
  tri::pair_contact_force({right}, a, b, c, dt, later);
  EXPECT_NEAR(tri::slot_shear(later, 0).x(), 1e-6, 1e-18);
  for (int s = 1; s < tri::kHistorySlots; ++s)
    EXPECT_FALSE(tri::slot_occupied(later, s));
  // No contacts: the history is cleared.
  tri::pair_contact_force({}, a, b, c, dt, later);
  for (double v : later)
    EXPECT_EQ(v, 0.0);
}

TEST(PairContactForce, MatchingIsByLeverAmongEqualNormals) {
  double history[tri::kHistoryDoubles] = {};
  const Vector3d down = -Vector3d::UnitZ();
  tri::write_slot(history, 0, down, Vector3d(1, 0, 0), Vector3d(0.001, 0, 0), 0.0);
  tri::write_slot(history, 1, down, Vector3d(2, 0, 0), Vector3d(-0.001, 0, 0), 0.0);
  const ContactPoint pts[2] = {point(Vector3d(-0.00099, 0, 0), down, 1e-4),
                               point(Vector3d(0.00101, 0, 0), down, 1e-4)};
  int slot[tri::kHistorySlots];
  tri::match_history(history, pts, 2, Vector3d::Zero(), slot);
  EXPECT_EQ(slot[0], 1);
  EXPECT_EQ(slot[1], 0);
  // A normal beyond the match angle never inherits a slot.
  const ContactPoint turned = point(Vector3d(0.001, 0, 0), Vector3d(1, 0, -0.9), 1e-4);
  tri::match_history(history, &turned, 1, Vector3d::Zero(), slot);
  EXPECT_EQ(slot[0], -1);
}

TEST(PairContactForce, StatisticsAreReturned) {
  const ContactCoefficients c = material();
  const BodyState a = body(Vector3d(0, 0, 0.002), Vector3d::Zero(), Vector3d::Zero(), 1e-3);
  const BodyState b = body(Vector3d(0, 0, -0.002), Vector3d::Zero(), Vector3d::Zero(), 1e-3);
  std::vector<ContactPoint> pts;
  for (int i = 0; i < 5; ++i)
    pts.push_back(point(Vector3d(1e-3 * i, 0, 0), -Vector3d::UnitZ(), 1e-5 * (i + 1)));
  pts[2].intersecting = true;
  pts[2].min_distance = 0.0;
  double history[tri::kHistoryDoubles] = {};
  const auto r = tri::pair_contact_force(pts, a, b, c, 1e-5, history);
  EXPECT_EQ(r.contacts_before, 15); // 5 points x 3 merged each
  EXPECT_EQ(r.contacts_after, 5);
  EXPECT_EQ(r.untracked, 1); // 5 points, 4 slots
  EXPECT_DOUBLE_EQ(r.max_overlap, 5e-5);
  EXPECT_EQ(r.min_distance, 0.0);
  EXPECT_TRUE(r.intersecting);
  const auto none = tri::pair_contact_force({}, a, b, c, 1e-5, history);
  EXPECT_EQ(none.contacts_after, 0);
  EXPECT_EQ(none.force_a, Vector3d::Zero());
}

// ---- a cube resting flat: no false torque ----

// n x n grid cells of two triangles on the square origin + [0, 1] s + [0, 1] t.
void add_grid(std::vector<Vector3d> &v, const Vector3d &origin, const Vector3d &s,
              const Vector3d &t, int n) {
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      auto at = [&](int di, int dj) {
        return Vector3d(origin + s * (double(i + di) / n) + t * (double(j + dj) / n));
      };
      for (const Vector3d &p : {at(0, 0), at(1, 0), at(1, 1), at(0, 0), at(1, 1), at(0, 1)})
        v.push_back(p);
    }
}

tri::TriangleSoA soa_of(const std::vector<Vector3d> &v) {
  tri::TriangleSoA s;
  s.resize(static_cast<int>(v.size() / 3));
  for (std::size_t i = 0; i < v.size(); ++i)
    s.set_vertex(static_cast<int>(i / 3), static_cast<int>(i % 3), v[i]);
  return s;
}

// Cube of side `side` (2 n^2 triangles per face) turned by `yaw` about z, centred at `centre`.
tri::TriangleSoA cube(double side, int n, const Vector3d &centre, double yaw) {
  std::vector<Vector3d> v;
  const double h = 0.5 * side;
  for (int axis = 0; axis < 3; ++axis)
    for (const double sign : {-1.0, 1.0}) {
      Vector3d o = Vector3d::Constant(-h), s = Vector3d::Zero(), t = Vector3d::Zero();
      o[axis] = sign * h;
      s[(axis + 1) % 3] = side;
      t[(axis + 2) % 3] = side;
      add_grid(v, o, s, t, n);
    }
  const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw, Vector3d::UnitZ()).toRotationMatrix();
  for (Vector3d &p : v)
    p = centre + R * p;
  return soa_of(v);
}

// The cube of the contact-point problem (4 mm, soft layers 0.1 mm) at rest on a plane, at an
// arbitrary place, meshed 2 to 128 triangles per face on a 2-triangle or a fine plane, turned
// or not, the plane as body a or b: the force is kn * overlap straight up and the torque about
// the cube's centre of mass is zero. With the kernel's closest points as contact point it was
// up to kn * overlap * 1.2 mm, enough to tip the cube.
TEST(PairContactForce, RestingCubeHasNoTorqueAboutItsCentreOfMass) {
  const double side = 0.004, eps = 1e-4, gap = 0.8 * eps, half_plane = 1.5 * side;
  ContactCoefficients c = material();
  tri::ReductionWorkspace work;
  std::vector<tri::TriangleContact> raw;
  std::vector<ContactPoint> points;
  double worst[2] = {0.0, 0.0}; // brute force, hybrid
  for (const int plane_n : {1, 16})
    for (const int n : {1, 2, 4, 8})
      for (const double yaw : {0.0, 0.7})
        for (const bool cube_is_a : {true, false})
          for (const auto kernel : {tri::DistanceKernel::BruteForce, tri::DistanceKernel::Hybrid}) {
            const Vector3d centre(0.41e-3, -0.27e-3, 0.5 * side + gap);
            const tri::TriangleSoA box = cube(side, n, centre, yaw);
            std::vector<Vector3d> pv;
            add_grid(pv, Vector3d(-half_plane, -half_plane, 0), Vector3d(2 * half_plane, 0, 0),
                     Vector3d(0, 2 * half_plane, 0), plane_n);
            const tri::TriangleSoA plane = soa_of(pv);
            const tri::TriangleSoA &ta = cube_is_a ? box : plane, &tb = cube_is_a ? plane : box;
            raw.clear();
            tri::ContactStats stats;
            tri::ContactOptions opt;
            opt.kernel = kernel;
            tri_test::find_triangle_contacts(ta, eps, tb, eps, opt, raw, stats);
            tri::ReductionParams params;
            params.link_length = tri::recommended_link_length(
                std::sqrt(2.0) * side / n, std::sqrt(2.0) * 2 * half_plane / plane_n, eps, eps);
            params.reference_direction = (cube_is_a ? -1.0 : 1.0) * Vector3d::UnitZ();
            tri::reduce_contacts(raw.data(), static_cast<int>(raw.size()), ta, eps, tb, eps, params,
                                 work, points);
            const BodyState cube_state = body(centre, Vector3d::Zero(), Vector3d::Zero(), 1e-4);
            const BodyState plane_state =
                body(Vector3d(0, 0, -0.01), Vector3d::Zero(), Vector3d::Zero(), 0.0);
            double history[tri::kHistoryDoubles] = {};
            const auto r =
                cube_is_a
                    ? tri::pair_contact_force(points, cube_state, plane_state, c, 1e-6, history)
                    : tri::pair_contact_force(points, plane_state, cube_state, c, 1e-6, history);
            const Vector3d force_on_cube = cube_is_a ? r.force_a : Vector3d(-r.force_a);
            const Vector3d torque_on_cube = cube_is_a ? r.torque_a : r.torque_b;
            const double weight = c.kn * (2 * eps - gap);
            ASSERT_EQ(r.contacts_after, 1);
            // The hybrid kernel's normal is exact to its tolerance (1e-4 eps in distance), not to
            // rounding: the lateral force that this leaves acts at the height of the centre.
            const double lateral = force_on_cube.head<2>().norm();
            const double slack =
                kernel == tri::DistanceKernel::Hybrid ? 1e-6 * weight : 1e-12 * weight;
            EXPECT_LE(lateral, slack);
            EXPECT_NEAR(force_on_cube.z(), weight, 1e-12 * weight);
            double &w = worst[kernel == tri::DistanceKernel::Hybrid];
            w = std::max(w, torque_on_cube.norm() / (weight * side));
            EXPECT_LE(torque_on_cube.norm(), 1e-9 * weight * side + lateral * side)
                << "tri/face " << 2 * n * n << " plane " << plane_n << " yaw " << yaw
                << " cube is a " << cube_is_a;
          }
  std::printf(
      "resting cube: largest |torque| / (weight * side) %.2e (brute force), %.2e (hybrid)\n",
      worst[0], worst[1]);
}

} // namespace

// ---- records for output: the virial ----

namespace {

// The records' virial of both bodies summed over a pair's contacts.
tri::Virial pair_virial(const std::vector<tri::ContactRecord> &records) {
  tri::Virial v{};
  for (const tri::ContactRecord &r : records)
    for (int k = 0; k < 6; ++k)
      v[k] += r.virial_a[k] + r.virial_b[k];
  return v;
}

} // namespace

TEST(ContactRecords, PairVirialIsTheBranchBetweenCentresTimesTheForce) {
  // Two off-centre contacts with friction and damping: whatever the points, forces along and
  // across the normal sum to (x_a - x_b) (x) F_a over both bodies (LIGGGHTS's pair virial).
  ContactCoefficients c = material();
  const BodyState a = body({0.001, -0.002, 0.0005}, {0.1, 0.02, -0.05}, {3, -1, 2}, 1e-4);
  const BodyState b = body({0.004, 0.001, 0.0015}, {-0.1, 0.0, 0.03}, {-2, 4, 1}, 2e-4);
  const ContactPoint p = point({0.0025, -0.0005, 0.001}, {1, 1, 0.3}, 6e-5);
  ContactPoint q = point({0.0027, -0.0009, 0.0012}, {1, 0.8, 0.4}, 3e-5);
  std::vector<tri::ContactRecord> records;
  double history[2 * tri::kHistoryDoubles] = {};
  const auto r = tri::pair_contact_force({p, q}, a, b, c, 1e-5, history, &records);
  ASSERT_EQ(records.size(), 2u);
  const tri::Virial v = pair_virial(records);
  tri::Virial expected{};
  tri::add_virial(a.x - b.x, r.force_a, expected);
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(v[k], expected[k], 1e-12 * r.force_a.norm() * (a.x - b.x).norm()) << k;
  // Pressed together: the trace is positive, as LIGGGHTS's pair virial of spheres.
  EXPECT_GT(v[0] + v[1] + v[2], 0.0);
  // The records carry the forces the result applies.
  Vector3d on_b = Vector3d::Zero();
  for (const tri::ContactRecord &rec : records)
    on_b += rec.force_on_b();
  EXPECT_NEAR((on_b + r.force_a).norm(), 0.0, 1e-12 * r.force_a.norm());
}

TEST(ContactRecords, AskingForRecordsChangesNoForce) {
  const ContactCoefficients c = material();
  const BodyState a = body({0, 0, 0}, {0.1, 0, 0}, {0, 0, 5}, 1e-4);
  const BodyState b = body({0.004, 0, 0}, {-0.1, 0, 0}, {0, 3, 0}, 1e-4);
  const ContactPoint p = point({0.002, 0.0003, 0}, {1, 0, 0}, 5e-5);
  double h1[tri::kHistoryDoubles] = {}, h2[tri::kHistoryDoubles] = {};
  std::vector<tri::ContactRecord> records;
  const auto plain = tri::pair_contact_force({p}, a, b, c, 1e-5, h1);
  const auto with = tri::pair_contact_force({p}, a, b, c, 1e-5, h2, &records);
  EXPECT_EQ(plain.force_a, with.force_a);
  EXPECT_EQ(plain.torque_a, with.torque_a);
  EXPECT_EQ(plain.torque_b, with.torque_b);
  for (int k = 0; k < tri::kHistoryDoubles; ++k)
    EXPECT_EQ(h1[k], h2[k]);
}
