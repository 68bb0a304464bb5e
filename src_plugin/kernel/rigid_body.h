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
