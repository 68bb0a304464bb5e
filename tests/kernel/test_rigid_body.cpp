// Tests of rigid_body.h: the NO_SQUISH free rotor against the invariants and the analytic
// solutions of torque-free rotation, and the seeded random orientations.
#include "body/rigid_body.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;

// Mass properties of a mm-sized rock (kg m^2), in the ratio 1:2:3 of a strongly
// asymmetric top; and its spin scale so that omega dt is the dimensionless step.
const double kInertiaScale = 1e-10;
const Vector3d kAsymmetric = Vector3d(1.0, 2.0, 3.0) * kInertiaScale;

struct Drift {
  double energy = 0.0;  // max |E - E0| / E0
  double angmom = 0.0;  // max |L - L0| / |L0|, L in the space frame
  double norm = 0.0;    // max ||L| - |L0|| / |L0|
  double secular = 0.0; // |mean E over last 10% - mean E over first 10%| / E0
};

// Integrates `steps` free steps from (q, L) and records the worst deviations.
Drift run_free(Quaterniond q, Vector3d l, const Vector3d &inertia, double dt, int steps) {
  const double e0 = tri::rotational_energy(q, l, inertia);
  const Vector3d l0 = l;
  Drift d;
  const int window = steps / 10;
  double first = 0.0, last = 0.0;
  for (int n = 0; n < steps; ++n) {
    tri::rotate_free(q, l, inertia, dt);
    const double e = tri::rotational_energy(q, l, inertia);
    d.energy = std::max(d.energy, std::abs(e - e0) / e0);
    d.angmom = std::max(d.angmom, (l - l0).norm() / l0.norm());
    d.norm = std::max(d.norm, std::abs(l.norm() - l0.norm()) / l0.norm());
    if (n < window)
      first += e;
    if (n >= steps - window)
      last += e;
  }
  d.secular = std::abs(last - first) / window / e0;
  return d;
}

// The body-frame angular velocity, the quantity whose components the stability tests watch.
Vector3d body_omega(const Quaterniond &q, const Vector3d &l, const Vector3d &inertia) {
  return tri::body_angmom(q, l).cwiseQuotient(inertia);
}

TEST(RigidBody, AsymmetricTopConservesEnergyAndAngularMomentum) {
  // Generic initial state: spin not near any principal axis, random orientation.
  const Quaterniond q = tri::random_orientation(1, 2);
  const Vector3d omega_body(0.6, -0.5, 0.7); // rad/s, times 1/dt scale below
  const double omega_scale = 100.0;          // rad/s: |omega| ~ 100 rad/s
  const double dt = 1e-6;                    // s: |omega| dt ~ 1.1e-4
  const Vector3d l = q * (kAsymmetric.cwiseProduct(omega_body) * omega_scale);
  const Drift d = run_free(q, l, kAsymmetric, dt, 100000); // ~11 rad turned, ~2 tumbles
  std::printf("asymmetric top, 1e5 steps, |w|dt=1.1e-4: max dE/E=%.3g secular dE/E=%.3g "
              "max|dL|/|L|=%.3g max d|L|/|L|=%.3g\n",
              d.energy, d.secular, d.angmom, d.norm);
  EXPECT_LT(d.energy, 1e-6);
  EXPECT_LT(d.secular, 1e-7);
  EXPECT_LT(d.angmom, 1e-12); // every sub-step conserves L_space exactly
  EXPECT_LT(d.norm, 1e-12);
}

TEST(RigidBody, AsymmetricTopLongRunHasNoSecularEnergyDrift) {
  // Ten times coarser step, over many tumbling periods: the energy error of a symplectic
  // scheme oscillates and stays bounded; it must not grow with the length of the run.
  const Quaterniond q = tri::random_orientation(3, 4);
  const Vector3d l = q * kAsymmetric.cwiseProduct(Vector3d(0.6, -0.5, 0.7) * 100.0);
  const Drift short_run = run_free(q, l, kAsymmetric, 1e-5, 10000);
  const Drift long_run = run_free(q, l, kAsymmetric, 1e-5, 100000);
  std::printf("asymmetric top, |w|dt=1.1e-3: max dE/E over 1e4 steps %.3g, over 1e5 steps %.3g "
              "(secular %.3g)\n",
              short_run.energy, long_run.energy, long_run.secular);
  EXPECT_LT(long_run.energy, 1e-5);
  EXPECT_LT(long_run.energy, 1.5 * short_run.energy);
  EXPECT_LT(long_run.angmom, 1e-12);
}

TEST(RigidBody, EnergyErrorIsSecondOrder) {
  const Quaterniond q = tri::random_orientation(5, 6);
  const Vector3d l = q * kAsymmetric.cwiseProduct(Vector3d(0.6, -0.5, 0.7) * 100.0);
  const double coarse = run_free(q, l, kAsymmetric, 4e-5, 5000).energy;
  const double fine = run_free(q, l, kAsymmetric, 2e-5, 10000).energy;
  const double ratio = coarse / fine;
  EXPECT_GT(ratio, 3.5) << "coarse " << coarse << " fine " << fine;
  EXPECT_LT(ratio, 4.5) << "coarse " << coarse << " fine " << fine;
}

TEST(RigidBody, StepIsTimeReversible) {
  const Quaterniond q0 = tri::random_orientation(7, 8);
  const Vector3d l0 = q0 * kAsymmetric.cwiseProduct(Vector3d(0.6, -0.5, 0.7) * 100.0);
  Quaterniond q = q0;
  Vector3d l = l0;
  for (int n = 0; n < 1000; ++n)
    tri::rotate_free(q, l, kAsymmetric, 1e-4);
  EXPECT_GT(q.angularDistance(q0), 1.0); // it did move
  for (int n = 0; n < 1000; ++n)
    tri::rotate_free(q, l, kAsymmetric, -1e-4);
  EXPECT_LT(q.angularDistance(q0), 1e-11);
  EXPECT_LT((l - l0).norm() / l0.norm(), 1e-12);
}

// Spins about body axis `axis` at 2 rad/s with a 1e-3 perturbation on the other two axes;
// returns the smallest and largest value of that body-frame omega component over 100 s.
std::pair<double, double> spin_range(int axis) {
  Vector3d omega_body = Vector3d::Constant(1e-3);
  omega_body[axis] = 2.0;
  Quaterniond q = tri::random_orientation(11, axis);
  Vector3d l = q * kAsymmetric.cwiseProduct(omega_body);
  double lo = omega_body[axis], hi = omega_body[axis];
  for (int n = 0; n < 100000; ++n) { // dt 1e-3 s, omega dt = 2e-3
    tri::rotate_free(q, l, kAsymmetric, 1e-3);
    const double w = body_omega(q, l, kAsymmetric)[axis];
    lo = std::min(lo, w);
    hi = std::max(hi, w);
  }
  return {lo, hi};
}

TEST(RigidBody, IntermediateAxisFlips) {
  // Dzhanibekov effect: the growth rate of a perturbation about the intermediate axis is
  // 2 * sqrt((I1-I0)(I2-I1)/(I0 I2)) = 1.15 rad/s, so a 5e-4 perturbation flips the spin
  // in about 7 s; over 100 s it flips many times, each time nearly to -2 rad/s.
  const auto [lo, hi] = spin_range(1);
  EXPECT_LT(lo, -1.9);
  EXPECT_GT(hi, 1.9);
}

TEST(RigidBody, SmallestAndLargestAxesAreStable) {
  for (int axis : {0, 2}) {
    const auto [lo, hi] = spin_range(axis);
    EXPECT_GT(lo, 2.0 * 0.98) << "axis " << axis;
    EXPECT_LT(hi, 2.0 * 1.02) << "axis " << axis;
  }
}

// Spherical top: omega = L / I is constant in space and the body turns about it uniformly.
// Returns the angle (rad) between the integrated and the analytic orientation after 10 rad.
double spherical_error(double dt, double *omega_dev) {
  const Vector3d inertia = Vector3d::Constant(2.0 * kInertiaScale);
  const Quaterniond q0 = tri::random_orientation(13, 14);
  const Vector3d omega(30.0, -40.0, 120.0); // rad/s, |omega| = 130
  Quaterniond q = q0;
  Vector3d l = omega * inertia[0];
  const int steps = static_cast<int>(std::lround(10.0 / 130.0 / dt));
  *omega_dev = 0.0;
  for (int n = 0; n < steps; ++n) {
    tri::rotate_free(q, l, inertia, dt);
    *omega_dev = std::max(*omega_dev, (tri::angular_velocity(q, l, inertia) - omega).norm());
  }
  const double t = steps * dt;
  const Quaterniond exact =
      Quaterniond(Eigen::AngleAxisd(omega.norm() * t, omega.normalized())) * q0;
  return q.angularDistance(exact);
}

TEST(RigidBody, SphericalTopFollowsAnalyticRotation) {
  double dev_coarse = 0.0, dev_fine = 0.0;
  const double coarse = spherical_error(1e-4, &dev_coarse);
  const double fine = spherical_error(0.5e-4, &dev_fine);
  std::printf("spherical top after 10 rad: angle error %.3g rad at |w|dt=0.013, %.3g at 0.0065\n",
              coarse, fine);
  // omega is exactly L / I at every step: L_space is conserved by every sub-step.
  EXPECT_LT(dev_coarse, 1e-11 * 130.0);
  EXPECT_LT(dev_fine, 1e-11 * 130.0);
  // The orientation follows the analytic rotation to second order in omega dt.
  EXPECT_LT(fine, 1e-3);
  EXPECT_GT(coarse / fine, 3.5);
  EXPECT_LT(coarse / fine, 4.5);
}

TEST(RigidBody, AngularVelocityAndEnergyAreConsistent) {
  const Quaterniond q = tri::random_orientation(17, 18);
  const Vector3d omega(1.0, -2.0, 0.5);
  const Vector3d l = tri::angmom_from_omega(q, omega, kAsymmetric);
  EXPECT_LT((tri::angular_velocity(q, l, kAsymmetric) - omega).norm(), 1e-14);
  const double energy = 0.5 * omega.dot(l);
  // A few roundings apart: relative 1e-13 (an absolute 1e-25 held only with FMA contraction).
  EXPECT_NEAR(tri::rotational_energy(q, l, kAsymmetric), energy, 1e-13 * std::abs(energy));
  // Body frame: L_body = I omega_body component by component.
  const Vector3d lb = tri::body_angmom(q, l);
  const Vector3d wb = q.conjugate() * omega;
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(lb[k], kAsymmetric[k] * wb[k], 1e-13 * l.norm());
}

TEST(RigidBody, RandomOrientationIsUnitDeterministicAndCanonical) {
  for (std::uint64_t key = 0; key < 1000; ++key) {
    const Quaterniond q = tri::random_orientation(99, key);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    EXPECT_GE(q.w(), 0.0);
    EXPECT_TRUE(q.coeffs() == tri::random_orientation(99, key).coeffs());
  }
  EXPECT_FALSE(tri::random_orientation(99, 1).coeffs() == tri::random_orientation(99, 2).coeffs());
  EXPECT_FALSE(tri::random_orientation(99, 1).coeffs() == tri::random_orientation(98, 1).coeffs());
  EXPECT_FALSE(tri::random_orientation(1, 2).coeffs() == tri::random_orientation(2, 1).coeffs());
  // Pinned values: orientations are part of a deck's reproducibility, across machines and
  // versions. A change here changes every simulation that uses `orient random`.
  const Quaterniond pinned = tri::random_orientation(99, 1);
  EXPECT_NEAR(pinned.w(), 0.64566560895596548, 1e-14);
  EXPECT_NEAR(pinned.x(), -0.12882032336084223, 1e-14);
  EXPECT_NEAR(pinned.y(), 0.75266036356260102, 1e-14);
  EXPECT_NEAR(pinned.z(), -0.004860331526105155, 1e-14);
}

TEST(RigidBody, RandomOrientationIsUniform) {
  // For the Haar measure E[R] = 0, E[R_ij^2] = 1/3 and E[w^2] = 1/4 (q uniform on S^3).
  // With N samples the standard error of a mean is about 0.6 / sqrt(N) at most.
  const int n = 40000;
  Eigen::Matrix3d mean = Eigen::Matrix3d::Zero(), mean_sq = Eigen::Matrix3d::Zero();
  double w2 = 0.0;
  for (int key = 0; key < n; ++key) {
    const Quaterniond q = tri::random_orientation(2024, static_cast<std::uint64_t>(key));
    const Eigen::Matrix3d r = q.toRotationMatrix();
    mean += r;
    mean_sq += r.cwiseProduct(r);
    w2 += q.w() * q.w();
  }
  mean /= n;
  mean_sq /= n;
  w2 /= n;
  const double tol = 5.0 * 0.6 / std::sqrt(static_cast<double>(n)); // 0.015
  EXPECT_LT(mean.cwiseAbs().maxCoeff(), tol) << mean;
  EXPECT_LT((mean_sq.array() - 1.0 / 3.0).abs().maxCoeff(), tol) << mean_sq;
  EXPECT_NEAR(w2, 0.25, tol);
}

} // namespace

// fix tri/nve advances all atoms at once with rotate_free_many (vectorised across atoms): each
// atom must get rotate_free's q and angular_velocity_unit's omega bit for bit, wherever it sits
// in the batch (its lane, the loop's remainder) and whatever the batch's size, or thread and
// rank counts would change trajectories. Batches of every size 1..19 from one set of 19 atoms
// (sizes above and below any vector width), one of them spinning so fast that its sub-step
// angle exceeds the series' range (the std::sin / std::cos pass).
TEST(RigidBody, BatchedRotorGivesEachAtomTheSingleRotorsBits) {
  const int count = 19, fast = 7;
  std::vector<Quaterniond> q0(count);
  std::vector<Vector3d> l0(count), inertia(count);
  for (int k = 0; k < count; ++k) {
    q0[k] = tri::random_orientation(5, k);
    inertia[k] = Vector3d(1.0 + 0.1 * k, 2.0 - 0.05 * k, 3.0 + 0.02 * k) * kInertiaScale;
    const double spin = k == fast ? 3e5 : 200.0 + 37.0 * k; // rad/s
    l0[k] = tri::angmom_from_omega(q0[k], spin * Vector3d(std::sin(k), std::cos(2.0 * k), 0.7).normalized(),
                                   inertia[k]);
  }
  const double dt = 2e-5;
  bool saw_fast = false;
  for (int size = 1; size <= count; ++size) {
    for (int first = 0; first + size <= count; first += std::max(1, size / 2)) {
      std::vector<double> qw, qx, qy, qz, lx, ly, lz, i0, i1, i2, v0, v1, v2;
      for (int k = first; k < first + size; ++k) {
        qw.push_back(q0[k].w()), qx.push_back(q0[k].x()), qy.push_back(q0[k].y()),
            qz.push_back(q0[k].z());
        lx.push_back(l0[k].x()), ly.push_back(l0[k].y()), lz.push_back(l0[k].z());
        i0.push_back(inertia[k].x()), i1.push_back(inertia[k].y()), i2.push_back(inertia[k].z());
        v0.push_back(1.0 / i0.back()), v1.push_back(1.0 / i1.back()), v2.push_back(1.0 / i2.back());
      }
      std::vector<double> wx(size), wy(size), wz(size);
      std::vector<int> large(size);
      for (int step = 0; step < 3; ++step) {
        tri::rotate_free_many(size, qw.data(), qx.data(), qy.data(), qz.data(), lx.data(),
                              ly.data(), lz.data(), v0.data(), v1.data(), v2.data(), dt,
                              wx.data(), wy.data(), wz.data(), large.data());
      }
      for (int j = 0; j < size; ++j) {
        const int k = first + j;
        Quaterniond q = q0[k];
        Vector3d l = l0[k];
        for (int step = 0; step < 3; ++step)
          tri::rotate_free(q, l, inertia[k], dt);
        const Vector3d w = tri::angular_velocity_unit(q, l, inertia[k].cwiseInverse());
        const std::string what = "atom " + std::to_string(k) + " of a batch of " +
                                 std::to_string(size) + " from " + std::to_string(first);
        ASSERT_EQ(q.w(), qw[j]) << what;
        ASSERT_EQ(q.x(), qx[j]) << what;
        ASSERT_EQ(q.y(), qy[j]) << what;
        ASSERT_EQ(q.z(), qz[j]) << what;
        ASSERT_EQ(l.x(), lx[j]) << what;
        ASSERT_EQ(w.x(), wx[j]) << what;
        ASSERT_EQ(w.y(), wy[j]) << what;
        ASSERT_EQ(w.z(), wz[j]) << what;
        saw_fast = saw_fast || (k == fast && large[j] != 0);
      }
    }
  }
  EXPECT_TRUE(saw_fast); // the std::sin / std::cos pass was exercised
}
