// The contact law of one contact point, split as in LAMMPS GRANULAR into small stateless
// sub-models (normal, tangential, kinematics) that share one coefficient struct. They follow
// LIGGGHTS 3.8 `pair gran model hooke/stiffness tangential history|no_history` exactly, so a
// deck written for spheres keeps its meaning. No host calls: dt and all coefficients are
// arguments. SI units throughout (m, s, kg, N).
//
// Sign conventions (every function here and in contact_force.h):
// - n: unit contact normal from body a towards body b.
// - v_rel = (v_b + w_b x (p - x_b)) - (v_a + w_a x (p - x_a)): velocity of b's material point
//   at the contact point p relative to a's.
// - v_n = v_rel . n: NEGATIVE while the bodies approach, positive while they separate
//   (the same sign as LIGGGHTS's vn). v_t = v_rel - v_n n.
// - F_n (scalar) > 0 is repulsive. The contact force ON B is F_n n + F_t; the force on a is
//   its negative. F_t is computed from b's relative motion, so it opposes v_t.
//
// Adding a sub-model: one function here, one enum value, one case in contact_force.cpp.
//
// Two deliberate departures from LIGGGHTS, both for contacts of flat faces, which spheres
// never have (each is a no-op for a sphere-like point contact at rest in the sense stated):
// - tangential_force_history caps the TOTAL tangential force (spring + damping) at mu |F_n|.
//   LIGGGHTS caps only the spring and adds -gamma_t v_t on top whenever the spring is below
//   the limit, so the total can exceed Coulomb. For spheres that hardly matters; for a face
//   contact that rocks (v_t at the contact point reverses with every rock, putting it back in
//   the sticking branch at full relative speed) the total reached 1.3 to 4 times F_n (2.6 to 8
//   times mu F_n) in edge impacts, braking a cube that should slide (validation/contact/
//   friction: 0.755 instead of 1.609 m/s^2 at 35 degrees, mu = 0.5). A tangential force above
//   mu |F_n| is not Coulomb friction: the spring and its damper act in parallel behind the
//   Coulomb slider, which cannot transmit more than mu |F_n| whatever drives it. The cap
//   changes nothing while the total is below mu |F_n|, i.e. for every sticking contact.
// - rocking_couple: a damping couple against the relative rotation about axes in the contact
//   plane, for contacts with an extent (patch_area > 0). LIGGGHTS has no such term (its
//   contacts are points).
// - friction_history / friction_no_history: twisting friction of a face-like contact (the
//   twist of b relative to a about n, w_n = (omega_b - omega_a) . n, resisted by the tangential
//   spring and damper spread over the patch, capped by Coulomb friction spread over it) sharing
//   one Coulomb budget with sliding. LIGGGHTS's spheres have none (a point does not resist
//   twist), and neither do our vertex and edge contacts: the twist is weighted by the
//   contact's face weight (contact_reduction.h step 6), 0 for them, so for them these are
//   exactly tangential_force_history / tangential_force_no_history.
#pragma once

#include "body/body_state.h"

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products

#include <string>

namespace tri {

enum class TangentialModel {
  history,   // LIGGGHTS tangential_model_history: spring on the shear displacement, Coulomb cap
  no_history // LIGGGHTS tangential_model_no_history: viscous friction capped by Coulomb
};

// One struct of coefficients, the values of LIGGGHTS's `fix property/global` entries for
// hooke/stiffness (looked up and mixed by the host for the pair's atom types).
struct ContactCoefficients {
  double kn = 0.0;               // N/m, normal stiffness
  double kt = 0.0;               // N/m, tangential stiffness (history model)
  double gamman = 0.0;           // 1/s (multiplied by m_eff), or kg/s with absolute_damping
  double gammat = 0.0;           // 1/s (multiplied by m_eff), or kg/s with absolute_damping
  double mu = 0.0;               // coefficient of friction, >= 0
  bool absolute_damping = false; // LIGGGHTS `absolute_damping on`: gammas are kg/s
  // LIGGGHTS `limitForce on`: F_n >= 0 (no attraction from the damper). LIGGGHTS's default is
  // off; the tri/gran deck default is on (repulsive only, as in the paper).
  bool limit_force = false;
  bool tangential_damping = true; // LIGGGHTS `tangential_damping on` (its default)
  TangentialModel tangential = TangentialModel::history;
};

// Empty when the coefficients are usable, else a message naming the offending one (the host
// turns it into error->all with the keyword). Checks finiteness and non-negativity.
std::string coefficient_error(const ContactCoefficients &c);

// m_eff = m_a m_b / (m_a + m_b), kg. A body with mass <= 0 or infinite is immovable (a wall):
// m_eff is then the other mass.
double effective_mass(double mass_a, double mass_b);

// Normal sub-model, hooke/stiffness: F_n = kn overlap - gamma_n v_n, with gamma_n = gamman
// m_eff (or gamman with absolute_damping); clamped to >= 0 with limit_force. overlap in m.
double normal_force(const ContactCoefficients &c, double overlap, double v_n, double m_eff);
// Its spring's potential energy, J: 1/2 kn Omega, Omega = the contact point's energy_overlap
// squared (contact_reduction.h: the spring force is the gradient of this energy).
double normal_elastic_energy(const ContactCoefficients &c, double energy_overlap);

// Tangential sub-model `history`. `shear` (m) is the contact's shear displacement, updated in
// place:  shear += v_t dt;  shear -= (shear . n) n  (onto the current tangent plane);
// F_t = -kt shear; if |F_t| > mu |F_n|: F_t *= mu |F_n| / |F_t| and shear = -F_t / kt
// (Coulomb cap; F_t = 0 if shear is zero), else F_t -= gamma_t v_t when tangential_damping
// (gamma_t = gammat m_eff, or gammat with absolute_damping) -- as LIGGGHTS so far -- and then,
// unlike LIGGGHTS (see above), if |F_t| > mu |F_n| the total is scaled down to mu |F_n|. The
// shear is left as it is in that case: the spring alone is within the limit, only the damper's
// share is cut, so no slip is recorded for what is a transient of the damper.
// Returns F_t (N) on b.
Eigen::Vector3d tangential_force_history(const ContactCoefficients &c, const Eigen::Vector3d &n,
                                         const Eigen::Vector3d &v_t, double f_n, double m_eff,
                                         double dt, Eigen::Vector3d &shear);

// Tangential sub-model `no_history`: F_t = -min(gamma_t |v_t|, mu |F_n|) v_t / |v_t|, zero when
// v_t = 0 (gamma_t as above). tangential_damping does not apply: here friction IS damping.
Eigen::Vector3d tangential_force_no_history(const ContactCoefficients &c,
                                            const Eigen::Vector3d &v_t, double f_n, double m_eff);

// Rocking damper of a face contact (patch_area > 0, contact_reduction.h step 6): the couple ON
// B, about the contact point, of a normal dashpot of total coefficient gamma_n (the normal
// sub-model's: gamman m_eff, or gamman with absolute_damping) spread uniformly over the patch,
// for the relative angular velocity w = omega_b - omega_a:
//   tau_b = -(gamma_n / A) K w,  K = integral over the patch of (r x n)(r x n)^T dA
//         = trace(J) P - J       (J = patch_second_moment, P = I - n n^T),
// since b's material at p + r moves along n, relative to a's, at (w x r) . n = w . (r x n).
// K n = 0: only w_perp = P w (rocking) is resisted, twisting about n is friction's business.
// The force of that dashpot, integral of -(gamma_n / A)(w . (r x n)) n dA, is zero about the
// area centroid, where a flat face contact's point is (contact_reduction.h step 5b; tilted, the
// point moves towards the low side and that force is neglected), so the result is a pure couple: it changes no momentum, and it dissipates
// (w . tau_b = -(gamma_n / A) w^T K w <= 0, K positive semi-definite). On a rocking face the
// resisting normal velocities are those of the distributed pressure: the couple adds to the
// point force's damping what the single point misses, so each in-plane axis gets damping
// gamma_n J_axis / A, that of a distributed dashpot (the stiffness of a tilting face comes from
// the point moving towards its low side, contact_reduction.h step 5b).
// With limit_force (a pressure that is nowhere negative) the couple is capped at
// |F_n| sqrt(2 trace(J) / A) (F_n times the radius of the disk with the patch's ratio of polar
// moment to area, the largest lever of a disk-shaped patch): a dashpot cannot pull the rising
// side of the face down harder than the contact presses. Zero when A <= 0 or gamma_n = 0.
Eigen::Vector3d rocking_couple(const ContactCoefficients &c, const Eigen::Vector3d &n,
                               double patch_area, const Eigen::Matrix3d &patch_second_moment,
                               const Eigen::Vector3d &omega_rel, double f_n, double m_eff);

// Twisting friction of a face-like contact: what the patch (contact_reduction.h step 6) gives
// the twist sub-model, both already multiplied by the contact's face weight w in [0, 1]:
//   lever          = w r_mean (m): with uniform pressure F_n / A on a flat region, Coulomb
//                    friction opposing a rotation about the point resists with
//                    integral of mu (F_n / A) |r| dA = mu F_n r_mean, r_mean = the region's mean
//                    distance from the point: the torque limit is T_max = mu |F_n| lever;
//   polar_per_area = w tr(J) / A (m^2): the tangential spring kt and damper gamma_t spread
//                    uniformly over the patch (kt / A per area, as the rocking damper spreads
//                    gamma_n) resist a twist by theta with integral of (kt / A) |r|^2 theta dA =
//                    kt (tr J / A) theta: twist stiffness k_w = kt polar_per_area (N m/rad),
//                    twist damping gamma_w = gamma_t polar_per_area (N m s/rad).
// A point-like contact (w = 0) has lever = polar_per_area = 0: no twist.
struct TwistPatch {
  double lever = 0.0;          // m
  double polar_per_area = 0.0; // m^2
  bool active() const { return lever > 0.0 && polar_per_area > 0.0; }
};

struct Friction {
  Eigen::Vector3d force = Eigen::Vector3d::Zero(); // N on b, in the tangent plane
  double twist_torque = 0.0; // N m on b about n (on a: the opposite); the couple is twist_torque n
};

// Sliding and twisting friction of a contact with history: `shear` (m) and `twist` (rad)
// are the contact's springs, updated in place. Without an active twist patch: twist = 0 and
// the force is tangential_force_history's, bit for bit. With one:
//   shear += v_t dt, projected onto the tangent plane (as tangential_force_history);
//   twist += w_n dt;
//   spring values F = -kt shear, T = -k_w twist;
//   the limit surface: an ellipse in (|F|, T) with half-axes F_max = mu |F_n| (sliding) and
//   T_max = F_max lever (twisting), s = sqrt((|F| / F_max)^2 + (T / T_max)^2);
//   s > 1 (slip): F /= s, T /= s, shear = -F / kt, twist = -T / k_w (radial return onto the
//   ellipse: sliding and twisting share one Coulomb budget; in steady slip the split follows the
//   ratio of the increments, kt |v_t| / F_max against k_w |w_n| / T_max);
//   else, with tangential_damping: F -= gamma_t v_t, T -= gamma_w w_n, and if that total is
//   outside the ellipse (s > 1) both are scaled by 1 / s, the springs unchanged (as the damped
//   total of tangential_force_history).
// The simplification: the exact limit surface of a uniformly pressed flat region (Goyal,
// Ruina and Papadopoulos 1991) is close to, not equal to, this ellipse (Howe and Cutkosky
// 1996 fit it with one); pure sliding and pure twisting are exact.
// F_max = 0 (no normal force or mu = 0): no friction, both springs zero.
Friction friction_history(const ContactCoefficients &c, const Eigen::Vector3d &n,
                          const Eigen::Vector3d &v_t, double w_n, double f_n, double m_eff,
                          double dt, const TwistPatch &patch, Eigen::Vector3d &shear,
                          double &twist);

// The same for tangential `no_history`: F = -gamma_t v_t, T = -gamma_w w_n, scaled onto the
// ellipse above when outside it; without an active twist patch tangential_force_no_history's.
Friction friction_no_history(const ContactCoefficients &c, const Eigen::Vector3d &v_t, double w_n,
                             double f_n, double m_eff, const TwistPatch &patch);

struct ContactKinematics {
  Eigen::Vector3d v_rel; // m/s, b relative to a at the contact point
  double v_n;            // m/s, v_rel . n (negative approaching)
  Eigen::Vector3d v_t;   // m/s, v_rel - v_n n
};

ContactKinematics contact_kinematics(const Eigen::Vector3d &p, const Eigen::Vector3d &n,
                                     const BodyState &a, const BodyState &b);

} // namespace tri
