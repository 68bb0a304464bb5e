// Contact sub-models (LIGGGHTS hooke/stiffness semantics); conventions in the header.
#include "model/contact_model.h"

#include <algorithm>
#include <cmath>

namespace tri {

using Eigen::Vector3d;

std::string coefficient_error(const ContactCoefficients &c) {
  const struct {
    const char *name;
    double value;
  } values[] = {{"kn", c.kn},
                {"kt", c.kt},
                {"gamman", c.gamman},
                {"gammat", c.gammat},
                {"coefficientFriction", c.mu}};
  for (const auto &v : values) {
    if (!std::isfinite(v.value))
      return std::string(v.name) + " is not finite";
    if (v.value < 0.0)
      return std::string(v.name) + " must be >= 0";
  }
  return std::string();
}

double effective_mass(double mass_a, double mass_b) {
  const bool wall_a = !(mass_a > 0.0) || !std::isfinite(mass_a);
  const bool wall_b = !(mass_b > 0.0) || !std::isfinite(mass_b);
  if (wall_b)
    return wall_a ? 0.0 : mass_a;
  if (wall_a)
    return mass_b;
  return mass_a * mass_b / (mass_a + mass_b);
}

double normal_force(const ContactCoefficients &c, double overlap, double v_n, double m_eff) {
  const double gamma = c.absolute_damping ? c.gamman : c.gamman * m_eff;
  const double f = c.kn * overlap - gamma * v_n;
  return c.limit_force ? std::max(f, 0.0) : f;
}

double normal_elastic_energy(const ContactCoefficients &c, double energy_overlap) {
  return 0.5 * c.kn * energy_overlap * energy_overlap;
}

Vector3d tangential_force_history(const ContactCoefficients &c, const Vector3d &n,
                                  const Vector3d &v_t, double f_n, double m_eff, double dt,
                                  Vector3d &shear) {
  shear += v_t * dt;
  shear -= shear.dot(n) * n;
  Vector3d f_t = -c.kt * shear;
  const double f_shear = f_t.norm();
  const double f_friction = c.mu * std::abs(f_n);
  if (f_shear > f_friction) {
    // Sliding: the spring is held at the Coulomb limit (f_shear > 0 implies kt > 0).
    f_t *= f_friction / f_shear;
    shear = -f_t / c.kt;
  } else if (c.tangential_damping) {
    const double gamma = c.absolute_damping ? c.gammat : c.gammat * m_eff;
    f_t -= gamma * v_t;
    // Unlike LIGGGHTS: the damped total obeys Coulomb too (header); the shear stays.
    const double f_total = f_t.norm();
    if (f_total > f_friction)
      f_t *= f_friction / f_total;
  }
  return f_t;
}

Vector3d rocking_couple(const ContactCoefficients &c, const Vector3d &n, double patch_area,
                        const Eigen::Matrix3d &patch_second_moment, const Vector3d &omega_rel,
                        double f_n, double m_eff) {
  const double gamma = c.absolute_damping ? c.gamman : c.gamman * m_eff;
  if (!(patch_area > 0.0) || !(gamma > 0.0))
    return Vector3d::Zero();
  const double polar = patch_second_moment.trace();
  const Eigen::Matrix3d k =
      polar * (Eigen::Matrix3d::Identity() - n * n.transpose()) - patch_second_moment;
  Vector3d tau = -(gamma / patch_area) * (k * omega_rel);
  if (c.limit_force) {
    const double cap = std::abs(f_n) * std::sqrt(2.0 * std::max(0.0, polar) / patch_area);
    const double size = tau.norm();
    if (size > cap)
      tau *= size > 0.0 ? cap / size : 0.0;
  }
  return tau;
}

namespace {

// Where (F, T) lies against the elliptic limit surface of half-axes f_max, t_max > 0.
double limit_ratio(const Vector3d &f, double t, double f_max, double t_max) {
  return std::hypot(f.norm() / f_max, t / t_max);
}

} // namespace

Friction friction_history(const ContactCoefficients &c, const Vector3d &n, const Vector3d &v_t,
                          double w_n, double f_n, double m_eff, double dt,
                          const TwistPatch &patch, Vector3d &shear, double &twist) {
  Friction r;
  if (!patch.active()) {
    twist = 0.0;
    r.force = tangential_force_history(c, n, v_t, f_n, m_eff, dt, shear);
    return r;
  }
  shear += v_t * dt;
  shear -= shear.dot(n) * n;
  twist += w_n * dt;
  const double f_max = c.mu * std::abs(f_n);
  if (!(f_max > 0.0)) {
    shear.setZero();
    twist = 0.0;
    return r;
  }
  const double t_max = f_max * patch.lever;
  const double k_twist = c.kt * patch.polar_per_area;
  r.force = -c.kt * shear;
  r.twist_torque = -k_twist * twist;
  const double s = limit_ratio(r.force, r.twist_torque, f_max, t_max);
  if (s > 1.0) {
    // Slip (s > 0 implies kt > 0): both springs held on the limit surface.
    r.force /= s;
    r.twist_torque /= s;
    shear = -r.force / c.kt;
    twist = -r.twist_torque / k_twist;
  } else if (c.tangential_damping) {
    const double gamma = c.absolute_damping ? c.gammat : c.gammat * m_eff;
    r.force -= gamma * v_t;
    r.twist_torque -= gamma * patch.polar_per_area * w_n;
    const double total = limit_ratio(r.force, r.twist_torque, f_max, t_max);
    if (total > 1.0) {
      r.force /= total;
      r.twist_torque /= total;
    }
  }
  return r;
}

Friction friction_no_history(const ContactCoefficients &c, const Vector3d &v_t, double w_n,
                             double f_n, double m_eff, const TwistPatch &patch) {
  Friction r;
  if (!patch.active()) {
    r.force = tangential_force_no_history(c, v_t, f_n, m_eff);
    return r;
  }
  const double f_max = c.mu * std::abs(f_n);
  if (!(f_max > 0.0))
    return r;
  const double gamma = c.absolute_damping ? c.gammat : c.gammat * m_eff;
  r.force = -gamma * v_t;
  r.twist_torque = -gamma * patch.polar_per_area * w_n;
  const double s = limit_ratio(r.force, r.twist_torque, f_max, f_max * patch.lever);
  if (s > 1.0) {
    r.force /= s;
    r.twist_torque /= s;
  }
  return r;
}

Vector3d tangential_force_no_history(const ContactCoefficients &c, const Vector3d &v_t, double f_n,
                                     double m_eff) {
  const double speed = v_t.norm();
  if (!(speed > 0.0))
    return Vector3d::Zero();
  const double gamma = c.absolute_damping ? c.gammat : c.gammat * m_eff;
  const double magnitude = std::min(gamma * speed, c.mu * std::abs(f_n));
  return -magnitude / speed * v_t;
}

ContactKinematics contact_kinematics(const Vector3d &p, const Vector3d &n, const BodyState &a,
                                     const BodyState &b) {
  ContactKinematics k;
  k.v_rel = (b.v + b.omega.cross(p - b.x)) - (a.v + a.omega.cross(p - a.x));
  k.v_n = k.v_rel.dot(n);
  k.v_t = k.v_rel - k.v_n * n;
  return k;
}

} // namespace tri
