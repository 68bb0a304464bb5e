// NO_SQUISH free rotor (Miller et al. 2002) and orientation helpers; see rigid_body.h.
#include "rigid_body.h"

#include <cassert>
#include <cmath>

namespace tri {
namespace {

// Quaternions as 4-vectors (w, x, y, z) so that the scheme reads as in the paper.
using Vec4 = Eigen::Vector4d;

Vec4 as_vec(const Eigen::Quaterniond &q) { return {q.w(), q.x(), q.y(), q.z()}; }

// P_k x = x (x) e_k, right multiplication by the unit quaternion of body axis k; the
// columns of the quaternion product matrix S(x) are x, P_0 x, P_1 x, P_2 x. For unit q,
// P_k q is the direction on S^3 in which q moves when the body turns about its axis k.
Vec4 permute(int k, const Vec4 &x) {
  switch (k) {
  case 0:
    return {-x[1], x[0], x[3], -x[2]};
  case 1:
    return {-x[2], -x[3], x[0], x[1]};
  default:
    return {-x[3], x[2], -x[1], x[0]};
  }
}

// Exact flow of h_k = (p . P_k q)^2 / (8 I_k) for time h: a rotation by 2 zeta of the
// pair (q, p) in the planes (q, P_k q) and (p, P_k p). zeta = h L_k / (2 I_k), so the body
// turns by omega_k h about its own axis k while L_k is unchanged.
void free_rotate(int k, double h, double inertia_k, Vec4 &q, Vec4 &p) {
  const Vec4 pq = permute(k, q);
  const double zeta = h * p.dot(pq) / (4.0 * inertia_k);
  const double c = std::cos(zeta), s = std::sin(zeta);
  const Vec4 pp = permute(k, p);
  q = c * q + s * pq;
  p = c * p + s * pp;
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
  q.normalize();
  const Eigen::Vector3d l_body = q.conjugate() * angmom_space;
  Vec4 qv = as_vec(q);
  // Conjugate momentum p = 2 S(q) (0, L_body).
  Vec4 p =
      2.0 * (l_body[0] * permute(0, qv) + l_body[1] * permute(1, qv) + l_body[2] * permute(2, qv));
  const Eigen::Vector3d &inertia = principal_inertia;
  free_rotate(2, 0.5 * dt, inertia[2], qv, p);
  free_rotate(1, 0.5 * dt, inertia[1], qv, p);
  free_rotate(0, dt, inertia[0], qv, p);
  free_rotate(1, 0.5 * dt, inertia[1], qv, p);
  free_rotate(2, 0.5 * dt, inertia[2], qv, p);
  // Each sub-step is an orthogonal map of (q, p), so |q| = 1 holds analytically; roundoff
  // makes it random-walk, and every consumer (toRotationMatrix, the world-frame triangles)
  // assumes a unit q: a norm of 1 + d would scale the particle by 1 + 2d. Renormalising is
  // a projection back onto the constraint surface the exact map already preserves, so it
  // only removes roundoff (p is rebuilt from q and L on the next call, so it needs none).
  q = Eigen::Quaterniond(qv[0], qv[1], qv[2], qv[3]);
  q.normalize();
  // angmom_space is left untouched: every R_k conserves L_space exactly (it turns the body
  // and counter-rotates L_body), so the advanced pair's L_space equals the input in exact
  // arithmetic. Re-expressing it as R(q') S(q')^T p / 2 was measured to add a roundoff
  // drift of |L| (3e-11 relative over 1e5 steps); keeping it makes L bitwise conserved.
}

Eigen::Vector3d body_angmom(const Eigen::Quaterniond &q, const Eigen::Vector3d &angmom_space) {
  return q.normalized().conjugate() * angmom_space;
}

Eigen::Vector3d angular_velocity(const Eigen::Quaterniond &q, const Eigen::Vector3d &angmom_space,
                                 const Eigen::Vector3d &principal_inertia) {
  const Eigen::Quaterniond u = q.normalized();
  const Eigen::Vector3d omega_body =
      (u.conjugate() * angmom_space).cwiseQuotient(principal_inertia);
  return u * omega_body;
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
