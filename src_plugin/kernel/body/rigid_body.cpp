// NO_SQUISH free rotor (Miller et al. 2002) and orientation helpers; see rigid_body.h.
#include "body/rigid_body.h"

#include <cassert>
#include <cmath>

namespace tri {
namespace {

// sin and cos of a sub-step's angle. A DEM step turns a particle by far less than 0.05 rad
// (omega dt/2 = 0.05 is 5000 rad/s at dt = 2e-5 s); there the Taylor series to x^11 and x^12
// leave a truncation error below 1e-21 (relative), so the values are sin and cos to an ulp or
// two at a fraction of a libm call (the rotation was most of a step in free flight). Both
// are exactly odd and even, as std::sin and std::cos, which keeps the step time-reversible.
// Beyond 0.05 rad: std::sin and std::cos if Libm, else the flag `large` (the caller redoes
// that particle with Libm; below 0.05 rad both give the same bits).
template <bool Libm>
inline __attribute__((always_inline)) void sub_step_sincos(double x, double &s, double &c,
                                                           int &large) {
  const double x2 = x * x;
  s = x * (1.0 + x2 * (-1.0 / 6.0 +
                       x2 * (1.0 / 120.0 +
                             x2 * (-1.0 / 5040.0 +
                                   x2 * (1.0 / 362880.0 + x2 * (-1.0 / 39916800.0))))));
  c = 1.0 + x2 * (-0.5 + x2 * (1.0 / 24.0 +
                               x2 * (-1.0 / 720.0 +
                                     x2 * (1.0 / 40320.0 +
                                           x2 * (-1.0 / 3628800.0 + x2 * (1.0 / 479001600.0))))));
  const bool big = !(std::fabs(x) <= 0.05);
  if constexpr (Libm) {
    if (big) {
      s = std::sin(x);
      c = std::cos(x);
    }
  } else {
    large = large | static_cast<int>(big);
  }
}

// One NO_SQUISH sub-step about body axis K for time h: the exact flow of
// h_K = (p . P_K q)^2 / (8 I_K), a rotation by 2 zeta of the pair (q, p) in the planes
// (q, P_K q) and (p, P_K p), zeta = h L_K / (2 I_K): the body turns by omega_K h about its own
// axis K while L_K is unchanged. P_K x = x (x) e_K is right multiplication by the unit
// quaternion of body axis K (the columns of the quaternion product matrix S(x) are x, P_0 x,
// P_1 x, P_2 x); for unit q, P_K q is the direction on S^3 in which q moves when the body
// turns about its axis K. Quaternions as 4-vectors (w, x, y, z), as in the paper.
template <int K> inline __attribute__((always_inline)) void permute(const double x[4], double y[4]) {
  if constexpr (K == 0) {
    y[0] = -x[1], y[1] = x[0], y[2] = x[3], y[3] = -x[2];
  } else if constexpr (K == 1) {
    y[0] = -x[2], y[1] = -x[3], y[2] = x[0], y[3] = x[1];
  } else {
    y[0] = -x[3], y[1] = x[2], y[2] = -x[1], y[3] = x[0];
  }
}

// `quarter_inverse_k` = 1 / (4 I_K): a product, not a division per sub-step (with the two
// normalisations, thirteen divisions a particle; as products a free-flight step of 512 rocks
// took 4 % less). zeta(-h) = -zeta(h) still holds exactly, so the step stays time-reversible.
template <int K, bool Libm>
inline __attribute__((always_inline)) void sub_step(double h, double quarter_inverse_k,
                                                    double q[4], double p[4], int &large) {
  double pq[4], pp[4];
  permute<K>(q, pq);
  permute<K>(p, pp);
  const double zeta =
      h * (p[0] * pq[0] + p[1] * pq[1] + p[2] * pq[2] + p[3] * pq[3]) * quarter_inverse_k;
  double c, s;
  sub_step_sincos<Libm>(zeta, s, c, large);
  for (int k = 0; k < 4; ++k) {
    q[k] = c * q[k] + s * pq[k];
    p[k] = c * p[k] + s * pp[k];
  }
}

// rotate_free on plain doubles: the one implementation behind rotate_free and
// rotate_free_many, so both give the same bits. q = (w, x, y, z) in and out.
// `inverse`: 1 / I_k, the principal moments' inverses.
template <bool Libm>
inline __attribute__((always_inline)) void rotor_step(double q[4], const double l[3],
                                                      const double inverse[3], double dt,
                                                      int &large) {
  const double r0 = 1.0 / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int k = 0; k < 4; ++k)
    q[k] *= r0;
  // L_body = R(q)^T L_space
  double r[9];
  rigid_detail::rotation_matrix(q, r);
  const double lb0 = r[0] * l[0] + r[3] * l[1] + r[6] * l[2];
  const double lb1 = r[1] * l[0] + r[4] * l[1] + r[7] * l[2];
  const double lb2 = r[2] * l[0] + r[5] * l[1] + r[8] * l[2];
  // Conjugate momentum p = 2 S(q) (0, L_body).
  double p0[4], p1[4], p2[4], p[4];
  permute<0>(q, p0);
  permute<1>(q, p1);
  permute<2>(q, p2);
  for (int k = 0; k < 4; ++k)
    p[k] = 2.0 * (lb0 * p0[k] + lb1 * p1[k] + lb2 * p2[k]);
  const double quarter[3] = {0.25 * inverse[0], 0.25 * inverse[1], 0.25 * inverse[2]};
  sub_step<2, Libm>(0.5 * dt, quarter[2], q, p, large);
  sub_step<1, Libm>(0.5 * dt, quarter[1], q, p, large);
  sub_step<0, Libm>(dt, quarter[0], q, p, large);
  sub_step<1, Libm>(0.5 * dt, quarter[1], q, p, large);
  sub_step<2, Libm>(0.5 * dt, quarter[2], q, p, large);
  // Each sub-step is an orthogonal map of (q, p), so |q| = 1 holds analytically; roundoff
  // makes it random-walk, and every consumer (toRotationMatrix, the world-frame triangles)
  // assumes a unit q: a norm of 1 + d would scale the particle by 1 + 2d. Renormalising is
  // a projection back onto the constraint surface the exact map already preserves, so it
  // only removes roundoff (p is rebuilt from q and L on the next call, so it needs none).
  const double r1 = 1.0 / std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int k = 0; k < 4; ++k)
    q[k] *= r1;
  // L_space is left untouched: every sub-step conserves it exactly (it turns the body and
  // counter-rotates L_body), so the advanced pair's L_space equals the input in exact
  // arithmetic. Re-expressing it as R(q') S(q')^T p / 2 was measured to add a roundoff drift
  // of |L| (3e-11 relative over 1e5 steps); keeping it makes L bitwise conserved.
}

// splitmix64's output function (Steele, Lea, Flood 2014): a bijective 64-bit mixer.
std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The top 53 bits as a double in [0, 1): exact, the same on every IEEE-754 machine.
double to_unit(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

} // namespace

void rotate_free(Eigen::Quaterniond &q, Eigen::Vector3d &angmom_space,
                 const Eigen::Vector3d &principal_inertia, double dt) {
  assert(principal_inertia.minCoeff() > 0.0);
  double qv[4] = {q.w(), q.x(), q.y(), q.z()};
  const double l[3] = {angmom_space[0], angmom_space[1], angmom_space[2]};
  // The inverses as fix tri/nve keeps them (1.0 / I_k), so both paths give the same bits.
  const double inverse[3] = {1.0 / principal_inertia[0], 1.0 / principal_inertia[1],
                             1.0 / principal_inertia[2]};
  int large = 0;
  rotor_step<true>(qv, l, inverse, dt, large);
  q = Eigen::Quaterniond(qv[0], qv[1], qv[2], qv[3]);
}

namespace {

// One particle of rotate_free_many (a function of its own: the `omp simd` lowering of the
// caller would turn these address-taken locals into per-lane arrays GCC cannot vectorise).
template <bool Libm>
inline __attribute__((always_inline)) void rotor_lane(int k, double *qw, double *qx, double *qy,
                                                      double *qz, const double *lx,
                                                      const double *ly, const double *lz,
                                                      const double *v0, const double *v1,
                                                      const double *v2, double dt, double *wx,
                                                      double *wy, double *wz, int *large_out) {
  double q[4] = {qw[k], qx[k], qy[k], qz[k]};
  const double l[3] = {lx[k], ly[k], lz[k]}, inverse[3] = {v0[k], v1[k], v2[k]};
  int large = 0;
  rotor_step<Libm>(q, l, inverse, dt, large);
  double w[3];
  rigid_detail::omega_of_unit(q, l, inverse, w);
  if constexpr (!Libm)
    large_out[k] = large;
  // a large-angle particle keeps its input for the second pass
  qw[k] = large ? qw[k] : q[0];
  qx[k] = large ? qx[k] : q[1];
  qy[k] = large ? qy[k] : q[2];
  qz[k] = large ? qz[k] : q[3];
  wx[k] = w[0], wy[k] = w[1], wz[k] = w[2];
}

} // namespace

void rotate_free_many(int n, double *qw, double *qx, double *qy, double *qz, const double *lx,
                      const double *ly, const double *lz, const double *v0, const double *v1,
                      const double *v2, double dt, double *wx, double *wy, double *wz,
                      int *large) {
  // All particles with the series, vectorised across particles; a particle that turns by
  // more than 0.05 rad in a sub-step keeps its input and is redone with std::sin and std::cos
  // (rotate_free's path: the same bits wherever the series is used).
#pragma omp simd
  for (int k = 0; k < n; ++k)
    rotor_lane<false>(k, qw, qx, qy, qz, lx, ly, lz, v0, v1, v2, dt, wx, wy, wz, large);
  for (int k = 0; k < n; ++k)
    if (large[k])
      rotor_lane<true>(k, qw, qx, qy, qz, lx, ly, lz, v0, v1, v2, dt, wx, wy, wz, large);
}

Eigen::Vector3d body_angmom(const Eigen::Quaterniond &q, const Eigen::Vector3d &angmom_space) {
  return q.normalized().conjugate() * angmom_space;
}

Eigen::Vector3d angular_velocity(const Eigen::Quaterniond &q, const Eigen::Vector3d &angmom_space,
                                 const Eigen::Vector3d &principal_inertia) {
  // R diag(1/I) R^T L with R the rotation of q/|q| (one matrix, no normalised copy of q).
  const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
  return r * (r.transpose() * angmom_space).cwiseQuotient(principal_inertia);
}

Eigen::Vector3d angmom_from_omega(const Eigen::Quaterniond &q, const Eigen::Vector3d &omega_space,
                                  const Eigen::Vector3d &principal_inertia) {
  const Eigen::Quaterniond u = q.normalized();
  const Eigen::Vector3d l_body = (u.conjugate() * omega_space).cwiseProduct(principal_inertia);
  return u * l_body;
}

double rotational_energy(const Eigen::Quaterniond &q, const Eigen::Vector3d &angmom_space,
                         const Eigen::Vector3d &principal_inertia) {
  const Eigen::Vector3d l_body = body_angmom(q, angmom_space);
  return 0.5 * l_body.cwiseProduct(l_body).cwiseQuotient(principal_inertia).sum();
}

Eigen::Quaterniond random_orientation(std::uint64_t seed, std::uint64_t key) {
  // Three independent words per (seed, key): the key is spread by a golden-ratio stride
  // (splitmix64's increment) so that word i of one key never equals word j of another for
  // any realistic tag, and the seed is mixed separately so (seed, key) and (key, seed) differ.
  const std::uint64_t gamma = 0x9e3779b97f4a7c15ULL;
  const std::uint64_t s = mix64(seed ^ 0x6a09e667f3bcc909ULL);
  double u[3];
  for (int i = 0; i < 3; ++i)
    u[i] = to_unit(mix64(s ^ mix64(key + static_cast<std::uint64_t>(i + 1) * gamma)));
  // Shoemake (Graphics Gems III, 1992): a uniform point on S^3 is a uniform rotation.
  const double two_pi = 6.283185307179586476925;
  const double a = std::sqrt(1.0 - u[0]), b = std::sqrt(u[0]);
  Eigen::Quaterniond q(b * std::cos(two_pi * u[2]), a * std::sin(two_pi * u[1]),
                       a * std::cos(two_pi * u[1]), b * std::sin(two_pi * u[2]));
  if (q.w() < 0.0)
    q.coeffs() = -q.coeffs();
  return q.normalized();
}

} // namespace tri
