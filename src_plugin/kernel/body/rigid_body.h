// Rigid-body rotation: a symplectic, time-reversible free-rotor step with the full inertia
// tensor (NO_SQUISH), and the small conversions around it that `fix tri/nve` needs.
//
// Reference: T. F. Miller III, M. Eleftheriou, P. Pattnaik, A. Ndirango, D. Newns and
// G. J. Martyna, "Symplectic quaternion scheme for biophysical molecular dynamics",
// J. Chem. Phys. 116, 8649 (2002).
//
// Conventions (all functions):
// - `q` rotates the body frame (the shape's principal axes) into the space frame:
//   x_space = q * x_body, i.e. R(q) = q.toRotationMatrix() has the body axes as columns.
//   q must be a unit quaternion on input (within ~1e-8; it is renormalised on use).
// - `angmom_space` is the angular momentum L in the SPACE frame, kg m^2/s. It is what the
//   LIGGGHTS fix carries per atom: torques (space frame) add to it directly.
// - `principal_inertia` holds the principal moments I_0, I_1, I_2 (kg m^2) about the body
//   axes x, y, z, in that order; any order of magnitudes, all > 0 (checked by assert only:
//   the shape code validates mass properties once, this is the per-step hot path).
// - Angular velocities are rad/s, energies J, dt in s.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>

namespace tri {

// Free (torque-free) rotation over dt by NO_SQUISH: the quaternion and its conjugate
// momentum p = 2 S(q) (0, L_body) are advanced by the symmetric splitting
//   R_z(dt/2) R_y(dt/2) R_x(dt) R_y(dt/2) R_z(dt/2),
// each R_k being the exact flow of h_k = L_k^2 / (2 I_k) (a rotation about body axis k).
// Second order, symplectic, time-reversible; L_space is conserved to roundoff by every
// sub-step and the energy error stays bounded (O((omega dt)^2), no secular drift).
// On return q is unit. angmom_space is not changed: each sub-step conserves L_space
// exactly (the body turns about its axis k and L_body counter-rotates), so the space-frame
// momentum of the advanced (q, p) pair IS the input; keeping it avoids a roundoff drift.
// It is a reference so the fix's update reads as one call per particle.
// A full step with torque is: L += dt/2 T; rotate_free(q, L, I, dt); L += dt/2 T'.
// Note: the splitting is not exact for a spherical top (the h_k do not commute); the
// orientation error there is O((omega dt)^2) per radian turned, like any other body.
void rotate_free(Eigen::Quaterniond &q, Eigen::Vector3d &angmom_space,
                 const Eigen::Vector3d &principal_inertia, double dt);

// Angular momentum in the body frame: R(q)^T L_space.
Eigen::Vector3d body_angmom(const Eigen::Quaterniond &q, const Eigen::Vector3d &angmom_space);

// Angular velocity in the space frame, rad/s: R diag(1/I) R^T L_space.
Eigen::Vector3d angular_velocity(const Eigen::Quaterniond &q, const Eigen::Vector3d &angmom_space,
                                 const Eigen::Vector3d &principal_inertia);

namespace rigid_detail {
// R(q) of a unit quaternion q = (w, x, y, z), row-major (r[3 i + j] = R_ij).
inline __attribute__((always_inline)) void rotation_matrix(const double q[4], double r[9]) {
  const double tx = 2.0 * q[1], ty = 2.0 * q[2], tz = 2.0 * q[3];
  const double twx = tx * q[0], twy = ty * q[0], twz = tz * q[0];
  const double txx = tx * q[1], txy = ty * q[1], txz = tz * q[1];
  const double tyy = ty * q[2], tyz = tz * q[2], tzz = tz * q[3];
  r[0] = 1.0 - (tyy + tzz), r[1] = txy - twz, r[2] = txz + twy;
  r[3] = txy + twz, r[4] = 1.0 - (txx + tzz), r[5] = tyz - twx;
  r[6] = txz - twy, r[7] = tyz + twx, r[8] = 1.0 - (txx + tyy);
}
// omega = R diag(1/I) R^T L for a unit q, from the inverse moments.
inline __attribute__((always_inline)) void omega_of_unit(const double q[4], const double l[3],
                                                         const double inverse[3], double w[3]) {
  double r[9];
  rotation_matrix(q, r);
  const double b0 = (r[0] * l[0] + r[3] * l[1] + r[6] * l[2]) * inverse[0];
  const double b1 = (r[1] * l[0] + r[4] * l[1] + r[7] * l[2]) * inverse[1];
  const double b2 = (r[2] * l[0] + r[5] * l[1] + r[8] * l[2]) * inverse[2];
  w[0] = r[0] * b0 + r[1] * b1 + r[2] * b2;
  w[1] = r[3] * b0 + r[4] * b1 + r[5] * b2;
  w[2] = r[6] * b0 + r[7] * b1 + r[8] * b2;
}
} // namespace rigid_detail

// The same for a unit q (rotate_free leaves it so) and the inverse principal moments
// 1/I_k: R diag(1/I) R^T L with no normalisation, the per-step form of fix tri/nve (the
// omega rotate_free_many returns, bit for bit; its second half step calls
// rigid_detail::omega_of_unit per atom). Equal to angular_velocity to rounding.
inline Eigen::Vector3d angular_velocity_unit(const Eigen::Quaterniond &q,
                                             const Eigen::Vector3d &angmom_space,
                                             const Eigen::Vector3d &inverse_inertia) {
  const double qv[4] = {q.w(), q.x(), q.y(), q.z()};
  const double l[3] = {angmom_space[0], angmom_space[1], angmom_space[2]};
  const double inv[3] = {inverse_inertia[0], inverse_inertia[1], inverse_inertia[2]};
  double w[3];
  rigid_detail::omega_of_unit(qv, l, inv, w);
  return {w[0], w[1], w[2]};
}

// rotate_free for n particles at once, vectorised across them (fix tri/nve's loop), in
// structure-of-arrays form: q = (qw, qx, qy, qz) advanced in place, bit for bit as rotate_free
// would; L (space frame) unchanged by the step; the inverses v0, v1, v2 of the principal moments
// (1.0 / I_k, which the caller keeps: the rotor needs no division by a moment); and the angular
// velocity of the advanced state, (wx, wy, wz) = angular_velocity_unit(q', L, (v0, v1, v2)) bit
// for bit. `scratch` holds n ints. All arrays of length n, not aliased.
void rotate_free_many(int n, double *qw, double *qx, double *qy, double *qz, const double *lx,
                      const double *ly, const double *lz, const double *v0, const double *v1,
                      const double *v2, double dt, double *wx, double *wy, double *wz,
                      int *scratch);

// Inverse of angular_velocity: L_space = R diag(I) R^T omega_space (e.g. to start a particle
// from a LIGGGHTS `omega`).
Eigen::Vector3d angmom_from_omega(const Eigen::Quaterniond &q, const Eigen::Vector3d &omega_space,
                                  const Eigen::Vector3d &principal_inertia);

// Rotational kinetic energy, J: sum_k L_body_k^2 / (2 I_k).
double rotational_energy(const Eigen::Quaterniond &q, const Eigen::Vector3d &angmom_space,
                         const Eigen::Vector3d &principal_inertia);

// A uniformly distributed random rotation (Haar measure on SO(3), Shoemake's subgroup
// algorithm) that depends only on (seed, key), e.g. key = atom tag, so orientations do not
// depend on the number of MPI ranks or the order atoms are visited. The bits come from
// splitmix64 and are mapped to doubles by hand (no std distributions, whose output is
// implementation-defined); results are identical wherever std::sin/cos/sqrt are correctly
// rounded to within an ulp. The sign is canonical (w >= 0, since q and -q are one rotation).
Eigen::Quaterniond random_orientation(std::uint64_t seed, std::uint64_t key);

} // namespace tri
