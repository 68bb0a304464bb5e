// From LIGGGHTS material properties (youngsModulus, poissonsRatio, coefficientRestitution,
// coefficientFriction, characteristicVelocity) to the coefficients of our linear
// spring-dashpot (contact_model.h), and the soft-layer width that goes with them. Pure
// functions, SI units; the host (src_plugin/liggghts/material_table.cpp) reads the properties
// and calls them.
//
// LIGGGHTS 3.8 facts used here (global_properties.cpp, normal_model_hooke.h,
// normal_model_hertz.h):
//   Y* = 1 / ((1 - nu_i^2) / Y_i + (1 - nu_j^2) / Y_j)
//   G* = 1 / (2 (2 - nu_i)(1 + nu_i) / Y_i + 2 (2 - nu_j)(1 + nu_j) / Y_j)
//   hooke: kn = 16/15 sqrt(reff) Y* (15 meff v_c^2 / (16 sqrt(reff) Y*))^(1/5), kt = kn,
//          gamman = sqrt(4 meff kn ln^2 e / (ln^2 e + pi^2)) (kg/s), gammat = gamman
//   hertz: kn = 4/3 Y* sqrt(reff delta), kt = 8 G* sqrt(reff delta),
//          gamman = 2 sqrt(5/6) (-beta) sqrt(2 Y* sqrt(reff delta) meff),
//          beta = ln e / sqrt(ln^2 e + pi^2),
//          gammat likewise with 8 G* sqrt(reff delta), so gammat / gamman = 2 sqrt(G* / Y*)
//   reff = ri rj / (ri + rj), meff = mi mj / (mi + mj); against a wall reff = ri, meff = mi.
// The hooke kn is exactly meff v_c^2 / delta_H^2, with delta_H the peak overlap of an undamped
// Hertz contact at v_c: the linear spring with Hertz's peak overlap at the characteristic
// velocity.
//
// Our contact (mesh particles, contact_model.h) has F_n = kn overlap - gamman meff v_n, linear
// in the overlap, with gamman in 1/s (times meff; kg/s with absolute_damping) and v_n < 0 while
// approaching. The mapping, per pair of atom types (and per particle type and wall type):
// - the two bodies are their volume-equivalent spheres: r = (3 V / (4 pi))^(1/3), m = rho V
//   (equivalent_sphere); a wall is a sphere of infinite radius and mass (reff = r, meff = m).
//   A type that may take several shapes (assign random) stands for the sphere of their MEAN
//   volume (equivalent_sphere_of_mean): its coefficients are exact for that body; a contact of
//   other shapes of the type has the same kn and gamman (1/s, times its own meff), so its
//   damping ratio is zeta sqrt(meff / meff_mean) and its restitution differs accordingly;
// - hooke: kn and kt as LIGGGHTS's hooke gives those two spheres at v_c;
// - hertz: the linear kn whose contact, damped as below, lasts as long as LIGGGHTS's damped
//   hertz contact of those spheres at v_c (liggghts_hertz_contact, its limitForce off
//   default): kn = meff (D(zeta) / t_LH)^2, D the dimensionless duration of our contact
//   (linear_duration_factor). Undamped (e = 1) that is Hertz's t_H = 2 I delta_H / v_c, I =
//   integral_0^1 (1 - x^(5/2))^(-1/2) dx = 1.47164, so kn = 1.1393 meff v_c^2 / delta_H^2, 1.14
//   times the hooke kn. The curvature radius is the volume-equivalent reff. kt is
//   Hertz-Mindlin's 8 G* sqrt(reff delta_s) at the overlap delta_s where Hertz's secant
//   stiffness 4/3 Y* sqrt(reff delta_s) equals kn, i.e. kt = 6 (G* / Y*) kn;
// - damping (both): the damping ratio zeta at which OUR linear spring-dashpot restitutes
//   exactly coefficientRestitution (damping_ratio_for_restitution; with limitForce on the
//   contact ends when the force reaches zero, not when the overlap does, which changes the
//   relation), gamman_abs = 2 zeta sqrt(kn meff); gammat_abs = gamman_abs for hooke and
//   gamman_abs 2 sqrt(G* / Y*) for hertz (LIGGGHTS's ratios), 0 with tangential_damping off;
//   stored divided by meff unless absolute_damping;
// - mu = coefficientFriction.
#pragma once

#include "model/contact_model.h"

namespace tri {

enum class MaterialModel {
  hooke_stiffness, // LIGGGHTS hooke/stiffness: kn, kt, gamman, gammat given directly
  hooke,           // LIGGGHTS hooke: from Y, nu, e, mu and the characteristic velocity
  hertz            // LIGGGHTS hertz, linearised at the characteristic velocity (above)
};

const char *material_model_name(MaterialModel m); // "hooke/stiffness", "hooke", "hertz"

// LIGGGHTS's mixing rules (Pa).
double effective_youngs_modulus(double y_i, double nu_i, double y_j, double nu_j);
double effective_shear_modulus(double y_i, double nu_i, double y_j, double nu_j);

// A body as LIGGGHTS would see it: a sphere of radius r (m) and mass m (kg). A wall has
// infinite radius and mass.
struct EquivalentSphere {
  double radius = 0.0;
  double mass = 0.0;
};

// r = (3 V / (4 pi))^(1/3), m = density V. V in m^3, density in kg/m^3.
EquivalentSphere equivalent_sphere(double volume, double density);
// The sphere standing for several shapes that one atom type may take (assign random): the
// volume-equivalent sphere of their MEAN volume (every shape is equally likely).
EquivalentSphere equivalent_sphere_of_mean(const double *volumes, int n, double density);
EquivalentSphere wall_sphere(); // infinite radius and mass

// reff = r_i r_j / (r_i + r_j), or r_i against a wall (r_j infinite).
double effective_radius(double r_i, double r_j);

// Undamped Hertz contact of two spheres closing at speed v (m/s): peak overlap
// delta_H = (15 meff v^2 / (16 Y* sqrt(reff)))^(2/5) (m), duration t_H = 2 I delta_H / v (s).
double hertz_peak_overlap(double y_eff, double reff, double meff, double v);
double hertz_contact_duration(double y_eff, double reff, double meff, double v);
// integral_0^1 (1 - x^(5/2))^(-1/2) dx = Gamma(2/5) sqrt(pi) / (5/2 Gamma(9/10))
constexpr double kHertzDurationIntegral = 1.4716375921623521;

// LIGGGHTS's hooke normal stiffness (N/m) at characteristic velocity v_c.
double liggghts_hooke_kn(double y_eff, double reff, double meff, double v_c);
// LIGGGHTS's hertz contact of two spheres closing at v (limitForce off): m x'' = -4/3 Y*
// sqrt(reff) x^(3/2) - gamma(x) x', gamma = 2 sqrt(5/6) |beta| sqrt(2 Y* sqrt(reff x) meff),
// integrated (RK4, 20000 steps per t_H; duration and restitution within about 1e-6) from
// x = 0 until x returns to 0. e = 1: undamped.
struct HertzContact {
  double duration = 0.0;     // s
  double restitution = 0.0;  // exit / impact speed
  double peak_overlap = 0.0; // m
};
HertzContact liggghts_hertz_contact(double y_eff, double reff, double meff, double v, double e);
// The linear stiffness (N/m) whose contact with damping ratio zeta (and limitForce) lasts as
// long as liggghts_hertz_contact(y_eff, reff, meff, v_c, e): meff (D(zeta) / t_LH)^2.
double hertz_equivalent_kn(double y_eff, double reff, double meff, double v_c, double e,
                           double zeta, bool limit_force);

// Our linear spring-dashpot, m x'' = -kn x - c x' while in contact (x the overlap), with
// damping ratio zeta = c / (2 sqrt(kn m)). Without limitForce the contact ends when x returns
// to 0: e = exp(-pi zeta / sqrt(1 - zeta^2)) (0 for zeta >= 1). With limitForce (F >= 0) it
// ends earlier, when kn x + c x' = 0, and e = exp(-zeta (pi - 2 asin zeta) / sqrt(1 - zeta^2))
// for zeta < 1, e = r^(zeta / sqrt(zeta^2 - 1)) with r = (zeta - s) / (zeta + s),
// s = sqrt(zeta^2 - 1), for zeta > 1 (e = exp(-2) at zeta = 1; Schwager & Poeschel 2007).
double linear_restitution(double zeta, bool limit_force);
// The inverse: zeta >= 0 such that linear_restitution(zeta, limit_force) = e, for 0 < e <= 1
// (1: zeta = 0). Without limitForce zeta = -ln e / sqrt(pi^2 + ln^2 e), LIGGGHTS's |beta|.
// Throws std::invalid_argument outside (0, 1].
double damping_ratio_for_restitution(double e, bool limit_force);
// Duration of that contact times omega_0 = sqrt(kn / m): 2 acos(zeta) / sqrt(1 - zeta^2) with
// limitForce (ln((zeta + s) / (zeta - s)) / s above zeta = 1, 2 at zeta = 1), pi / sqrt(1 -
// zeta^2) without (infinite for zeta >= 1: the overlap never returns to 0).
double linear_duration_factor(double zeta, bool limit_force);
// The duration in s: linear_duration_factor / sqrt(kn / meff).
double linear_contact_duration(double kn, double meff, double zeta, bool limit_force);

// What the material fixes say for one pair of types (or particle type and wall type).
struct MaterialProperties {
  double y_eff = 0.0;       // Pa, effective_youngs_modulus
  double g_eff = 0.0;       // Pa, effective_shear_modulus
  double restitution = 1.0; // coefficientRestitution, (0, 1]
  double friction = 0.0;    // coefficientFriction, >= 0
  double v_char = 0.0;      // m/s, characteristicVelocity
};

// The coefficients of our contact for `model` hooke or hertz between two equivalent spheres
// (wall: b = wall_sphere()). `switches` supplies the flags (absolute_damping, limit_force,
// tangential_damping, tangential model), which are kept. Throws std::invalid_argument naming
// the property when a value is out of range (Y* or G* <= 0, e outside (0, 1], mu < 0,
// v_char <= 0, a sphere without positive radius and mass).
ContactCoefficients map_material(MaterialModel model, const MaterialProperties &p,
                                 const EquivalentSphere &a, const EquivalentSphere &b,
                                 const ContactCoefficients &switches);

// The soft layer for `epsilon auto`. A head-on contact at relative speed v between bodies of
// effective mass meff on a spring kn reaches (undamped; damping only lessens it) the peak
// overlap delta = v sqrt(meff / kn). Two layers of width epsilon give 2 epsilon of overlap
// before the real surfaces meet; the rule keeps delta at `fraction` (default 0.5) of that:
// epsilon = delta / (2 fraction), i.e. epsilon = delta for the default.
double peak_overlap(double kn, double meff, double v);
constexpr double kAutoEpsilonFraction = 0.5;
double auto_epsilon(double kn, double meff, double v, double fraction = kAutoEpsilonFraction);

} // namespace tri
