// Force and torques of one particle pair (or particle-wall pair) from its reduced contact
// points: what pair tri/gran and fix tri/wall call per pair per step. Each contact point gets
// the sub-models of contact_model.h (sign conventions there); the friction history (shear and twist)
// lives in the host's per-pair array (layout and matching in contact_history.h).
//
// Per contact point p with normal n and overlap delta:
//   kinematics at p (rotation included), F_n = normal_force(...) (for a patch, patch_area
//   > 0, its dashpot part with v_n at the patch's area centre c_A and acting there, the spring
//   part at p: contact_reduction.h step 6), (F_t, T_w) = friction sub-
//   model (friction_history or friction_no_history: sliding and, for a face-like contact,
//   twisting, w_n = (omega_b - omega_a) . n), F_b = F_n n + F_t (on b), F_a = -F_b;
//   torque_a += (p - x_a) x F_a - T_w n, torque_b += (p - x_b) x F_b + T_w n, friction
//   included; for a face contact (patch_area > 0) also the rocking damper's couple, in
//   proportion to the face weight w (contact_reduction.h step 6: a face lying flat rocks on
//   the other; a ball rolling over nearly flat facets, whose overlap is a cone, w = 0, is not
//   braked), C_b = w rocking_couple(..., omega_b - omega_a, F_n, ...): torque_b += C_b,
//   torque_a -= C_b (contact_model.h: a pure couple that dissipates the relative rocking a
//   single force point cannot see). Hence F_a + F_b = 0 and total angular momentum is
//   conserved about any point: (x_a - o) x F_a + torque_a + (x_b - o) x F_b + torque_b = 0
//   (to rounding).
// Statistics are returned, never kept.
#pragma once

#include "contact/contact_point.h"
#include "model/contact_history.h"
#include "model/contact_model.h"

#include <Eigen/Core>

#include <array>
#include <limits>
#include <vector>

namespace tri {

// A virial, N m, in LIGGGHTS's order xx yy zz xy xz yz: sum over forces F acting on a body of
// (x - p) (x) F, x the body's centre of mass and p where F acts. Summed over both bodies of a
// contact it is (x_a - x_b) (x) F_a for forces along one line, LIGGGHTS's pair virial of
// spheres, positive when the bodies are pressed together.
using Virial = std::array<double, 6>;
void add_virial(const Eigen::Vector3d &branch, const Eigen::Vector3d &force, Virial &v);

// One contact point as the force law saw it, for output (stress, the contact network); filled
// only where the caller asks (pair_contact_force's `records`).
struct ContactRecord {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // m, where the spring and friction act
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ(); // unit, from a towards b
  double normal_force = 0.0; // N along `normal` on b (spring and dashpot; on a: the opposite)
  Eigen::Vector3d tangential_force = Eigen::Vector3d::Zero(); // N on b (friction)
  double overlap = 0.0;      // m (ContactPoint::overlap)
  double area = 0.0;         // m^2, a face contact's patch; 0 point-like
  double mean_radius = 0.0;  // m, the patch's mean distance from `point` (0 point-like)
  ContactKind kind = ContactKind::vertex;
  int tri_a = -1, tri_b = -1; // the deepest member's triangles (indices into a's and b's)
  Eigen::Vector3d torque_a = Eigen::Vector3d::Zero(); // N m on a about its centre, couples too
  Eigen::Vector3d velocity_b = Eigen::Vector3d::Zero(); // m/s, b's material at `point`
  // The contact's virial on each body (Virial above), from the points where its forces act:
  // spring and friction at `point`, a face's dashpot at its area centre.
  Virial virial_a{}, virial_b{};
  Eigen::Vector3d force_on_b() const { return normal_force * normal + tangential_force; }
};

struct PairForceResult {
  Eigen::Vector3d force_a = Eigen::Vector3d::Zero();  // N on a; the force on b is -force_a
  Eigen::Vector3d torque_a = Eigen::Vector3d::Zero(); // N m on a about x_a
  Eigen::Vector3d torque_b = Eigen::Vector3d::Zero(); // N m on b about x_b (walls: ignore)
  int contacts_before = 0;  // triangle-pair contacts reduced into the points (sum num_merged)
  int contacts_after = 0;   // contact points
  int untracked = 0;        // points beyond kHistorySlots: no shear carried this step
  double max_overlap = 0.0; // m, deepest penetration of the soft layers
  double min_distance = std::numeric_limits<double>::infinity(); // m, closest triangle pair
  bool intersecting = false; // some triangles intersect (the soft layer was overrun)
  double elastic_energy = 0.0; // J, the normal springs' energy summed over the contact points
  // Set by body_interaction (penetration_depth.h): the combined soft layer eps_a + eps_b (m) and
  // the deepest the real surfaces may intersect, max_overlap - layer (m; infinity: no limit).
  double layer = 0.0;
  double depth_limit = std::numeric_limits<double>::infinity();
  // How far beyond the layer the deepest contact reaches, in units of depth_limit (> 1: deeper
  // than the model resolves); 0 when the surfaces do not intersect.
  double depth_of_limit() const {
    return intersecting && max_overlap > layer ? (max_overlap - layer) / depth_limit : 0.0;
  }
};

// `history`: kHistoryDoubles values of this pair, read and rewritten (tangential `history`
// model); ignored and may be null for `no_history`. dt > 0 in s. With no contacts the history
// is cleared and the result is zero.
// The twisting-friction patch of a contact (contact_model.h TwistPatch): lever = face_weight x
// patch_mean_radius, polar_per_area = face_weight x trace(patch_second_moment) / patch_area;
// inactive (zero) for a point-like contact.
TwistPatch twist_patch_of(const ContactPoint &c);

// `records`: null, or where one ContactRecord per contact point is appended (in `contacts`'
// order); the forces do not depend on it.
PairForceResult pair_contact_force(const std::vector<ContactPoint> &contacts, const BodyState &a,
                                   const BodyState &b, const ContactCoefficients &coeff, double dt,
                                   double *history,
                                   std::vector<ContactRecord> *records = nullptr);

} // namespace tri
