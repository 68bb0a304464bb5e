// Force and torques of one pair from its contact points; see contact_force.h.
#include "model/contact_force.h"

#include <algorithm>

namespace tri {

using Eigen::Vector3d;

TwistPatch twist_patch_of(const ContactPoint &c) {
  TwistPatch t;
  if (c.patch_area > 0.0 && c.face_weight > 0.0) {
    t.lever = c.face_weight * c.patch_mean_radius;
    t.polar_per_area = c.face_weight * c.patch_second_moment.trace() / c.patch_area;
  }
  return t;
}

void add_virial(const Vector3d &branch, const Vector3d &force, Virial &v) {
  v[0] += branch.x() * force.x();
  v[1] += branch.y() * force.y();
  v[2] += branch.z() * force.z();
  v[3] += branch.x() * force.y();
  v[4] += branch.x() * force.z();
  v[5] += branch.y() * force.z();
}

namespace {

// Contact c's record: its spring and friction f_b at c.point, its dashpot d_b at damping_point.
ContactRecord contact_record(const ContactPoint &c, const BodyState &a, const BodyState &b,
                             const Vector3d &f_b, double f_damper, double f_n,
                             const Vector3d &friction, const Vector3d &damping_point) {
  ContactRecord rec;
  rec.point = c.point;
  rec.normal = c.normal;
  rec.normal_force = f_n;
  rec.tangential_force = friction;
  rec.overlap = c.overlap;
  rec.area = c.patch_area;
  rec.mean_radius = c.patch_mean_radius;
  rec.kind = c.intersecting ? ContactKind::deep : c.kind;
  rec.tri_a = c.tri_a;
  rec.tri_b = c.tri_b;
  rec.velocity_b = b.v + b.omega.cross(c.point - b.x);
  add_virial(a.x - c.point, -f_b, rec.virial_a);
  add_virial(b.x - c.point, f_b, rec.virial_b);
  if (f_damper != 0.0) {
    const Vector3d d_b = f_damper * c.normal;
    add_virial(a.x - damping_point, -d_b, rec.virial_a);
    add_virial(b.x - damping_point, d_b, rec.virial_b);
  }
  return rec;
}

} // namespace

PairForceResult pair_contact_force(const std::vector<ContactPoint> &contacts, const BodyState &a,
                                   const BodyState &b, const ContactCoefficients &coeff, double dt,
                                   double *history, std::vector<ContactRecord> *records) {
  PairForceResult r;
  const int n = static_cast<int>(contacts.size());
  const bool with_history = coeff.tangential == TangentialModel::history && history != nullptr;
  int slot_of[kHistorySlots];
  double next[kHistoryDoubles] = {};
  // Levers are measured from a point that does not depend on which body is called a: the
  // midpoint of two particles (LIGGGHTS may swap i and j of a pair between neighbour-list
  // builds, see history_flips_sign), or the particle's centre against a wall (mass 0).
  const Vector3d origin = b.mass > 0.0 ? Vector3d(0.5 * (a.x + b.x)) : a.x;
  const int old_slots = with_history ? occupied_slots(history) : 0;
  if (with_history)
    match_history(history, contacts.data(), n, origin, slot_of);

  const double m_eff = effective_mass(a.mass, b.mass);
  for (int i = 0; i < n; ++i) {
    const ContactPoint &c = contacts[i];
    const ContactKinematics k = contact_kinematics(c.point, c.normal, a, b);
    // The dashpot at the patch's area centre (contact_reduction.h step 6): measured there and
    // acting there, so that its power is -gamma v_n^2 there; the spring at the point.
    const bool patch = c.patch_area > 0.0;
    const Vector3d damping_point = patch ? c.damping_point : c.point;
    const double v_n =
        patch ? contact_kinematics(damping_point, c.normal, a, b).v_n : k.v_n;
    const double f_n = normal_force(coeff, c.overlap, v_n, m_eff);
    const double f_spring = patch ? normal_force(coeff, c.overlap, 0.0, m_eff) : f_n;
    const double f_damper = f_n - f_spring;
    r.elastic_energy += normal_elastic_energy(coeff, c.energy_overlap);
    const TwistPatch twist_patch = twist_patch_of(c);
    const double w_n = (b.omega - a.omega).dot(c.normal);
    Friction friction;
    switch (coeff.tangential) {
    case TangentialModel::history: {
      const bool tracked = with_history && i < kHistorySlots;
      Vector3d shear = Vector3d::Zero();
      double twist = 0.0;
      if (tracked && slot_of[i] >= 0) {
        shear = slot_shear(history, slot_of[i]);
        twist = slot_twist(history, slot_of[i]);
      }
      friction =
          friction_history(coeff, c.normal, k.v_t, w_n, f_n, m_eff, dt, twist_patch, shear, twist);
      if (tracked)
        write_slot(next, i, c.normal, shear, c.point - origin, twist);
      else
        ++r.untracked;
      break;
    }
    case TangentialModel::no_history:
      friction = friction_no_history(coeff, k.v_t, w_n, f_n, m_eff, twist_patch);
      break;
    }
    const Vector3d f_b = f_spring * c.normal + friction.force;
    const Vector3d torque_a_before = records ? r.torque_a : Vector3d::Zero();
    r.force_a -= f_b;
    r.torque_a -= (c.point - a.x).cross(f_b);
    r.torque_b += (c.point - b.x).cross(f_b);
    if (f_damper != 0.0) {
      const Vector3d d_b = f_damper * c.normal;
      r.force_a -= d_b;
      r.torque_a -= (damping_point - a.x).cross(d_b);
      r.torque_b += (damping_point - b.x).cross(d_b);
    }
    if (friction.twist_torque != 0.0) {
      const Vector3d couple_b = friction.twist_torque * c.normal;
      r.torque_a -= couple_b;
      r.torque_b += couple_b;
    }
    if (c.patch_area > 0.0 && c.face_weight > 0.0) {
      // In proportion to the face weight (contact_reduction.h step 6): a patch of facets
      // under a rolling ball (a cone of overlap, face weight 0) is not braked.
      const Vector3d couple_b =
          c.face_weight * rocking_couple(coeff, c.normal, c.patch_area, c.patch_second_moment,
                                         b.omega - a.omega, f_n, m_eff);
      r.torque_a -= couple_b;
      r.torque_b += couple_b;
    }
    if (records) {
      records->push_back(
          contact_record(c, a, b, f_b, f_damper, f_n, friction.force, damping_point));
      records->back().torque_a = r.torque_a - torque_a_before;
    }
    r.contacts_before += c.num_merged;
    r.max_overlap = std::max(r.max_overlap, c.overlap);
    r.min_distance = std::min(r.min_distance, c.min_distance);
    r.intersecting = r.intersecting || c.intersecting;
  }
  r.contacts_after = n;
  // Slot k holds tracked contact k; beyond the slots occupied before and now, both are empty.
  if (with_history) {
    const int slots = std::max(old_slots, std::min(n, kHistorySlots));
    std::copy(next, next + slots * kHistorySlotDoubles, history);
  }
  return r;
}

} // namespace tri
