// Material properties to contact coefficients; the rules and their derivations are in the
// header.
#include "model/material_mapping.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace tri {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

void require(bool ok, const std::string &what) {
  if (!ok)
    throw std::invalid_argument(what);
}

// ln e of our linear spring-dashpot at damping ratio zeta (header). -inf where the contact
// never restitutes (zeta >= 1 without limitForce).
double log_restitution(double zeta, bool limit_force) {
  if (zeta <= 0.0)
    return 0.0;
  if (!limit_force)
    return zeta < 1.0 ? -kPi * zeta / std::sqrt(1.0 - zeta * zeta)
                      : -std::numeric_limits<double>::infinity();
  if (zeta < 1.0) // pi - 2 asin(zeta) = 2 acos(zeta), the better conditioned form near 1
    return -zeta * 2.0 * std::acos(zeta) / std::sqrt(1.0 - zeta * zeta);
  if (zeta == 1.0)
    return -2.0;
  const double s = std::sqrt(zeta * zeta - 1.0);
  return (zeta / s) * std::log1p(-2.0 * s / (zeta + s)); // ln((zeta - s) / (zeta + s))
}

} // namespace

const char *material_model_name(MaterialModel m) {
  switch (m) {
  case MaterialModel::hooke:
    return "hooke";
  case MaterialModel::hertz:
    return "hertz";
  case MaterialModel::hooke_stiffness:
    break;
  }
  return "hooke/stiffness";
}

double effective_youngs_modulus(double y_i, double nu_i, double y_j, double nu_j) {
  return 1.0 / ((1.0 - nu_i * nu_i) / y_i + (1.0 - nu_j * nu_j) / y_j);
}

double effective_shear_modulus(double y_i, double nu_i, double y_j, double nu_j) {
  return 1.0 / (2.0 * (2.0 - nu_i) * (1.0 + nu_i) / y_i + 2.0 * (2.0 - nu_j) * (1.0 + nu_j) / y_j);
}

EquivalentSphere equivalent_sphere(double volume, double density) {
  return {std::cbrt(3.0 * volume / (4.0 * kPi)), density * volume};
}

EquivalentSphere equivalent_sphere_of_mean(const double *volumes, int n, double density) {
  double sum = 0.0;
  for (int k = 0; k < n; ++k)
    sum += volumes[k];
  return equivalent_sphere(n > 0 ? sum / n : 0.0, density);
}

EquivalentSphere wall_sphere() {
  const double inf = std::numeric_limits<double>::infinity();
  return {inf, inf};
}

double effective_radius(double r_i, double r_j) {
  if (std::isinf(r_j))
    return r_i;
  if (std::isinf(r_i))
    return r_j;
  return r_i * r_j / (r_i + r_j);
}

double hertz_peak_overlap(double y_eff, double reff, double meff, double v) {
  return std::pow(15.0 * meff * v * v / (16.0 * y_eff * std::sqrt(reff)), 0.4);
}

double hertz_contact_duration(double y_eff, double reff, double meff, double v) {
  return 2.0 * kHertzDurationIntegral * hertz_peak_overlap(y_eff, reff, meff, v) / v;
}

double liggghts_hooke_kn(double y_eff, double reff, double meff, double v_c) {
  const double sqrt_r = std::sqrt(reff);
  return 16.0 / 15.0 * sqrt_r * y_eff *
         std::pow(15.0 * meff * v_c * v_c / (16.0 * sqrt_r * y_eff), 0.2);
}

HertzContact liggghts_hertz_contact(double y_eff, double reff, double meff, double v, double e) {
  const double le = std::log(e);
  const double beta = le / std::sqrt(le * le + kPi * kPi); // <= 0
  const double sqrt_r = std::sqrt(reff);
  auto acc = [&](double x, double u) {
    if (x <= 0.0)
      return 0.0;
    const double root = std::sqrt(x);
    const double spring = 4.0 / 3.0 * y_eff * sqrt_r * x * root;
    const double gamma =
        -2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(2.0 * y_eff * sqrt_r * root * meff);
    return -(spring + gamma * u) / meff;
  };
  const double h = hertz_contact_duration(y_eff, reff, meff, v) / 20000.0;
  HertzContact c;
  double x = 0.0, u = v, t = 0.0;
  for (int k = 0; k < 2000000; ++k) {
    const double k1x = u, k1u = acc(x, u);
    const double k2x = u + 0.5 * h * k1u, k2u = acc(x + 0.5 * h * k1x, u + 0.5 * h * k1u);
    const double k3x = u + 0.5 * h * k2u, k3u = acc(x + 0.5 * h * k2x, u + 0.5 * h * k2u);
    const double k4x = u + h * k3u, k4u = acc(x + h * k3x, u + h * k3u);
    const double xn = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    const double un = u + h / 6.0 * (k1u + 2.0 * k2u + 2.0 * k3u + k4u);
    if (xn <= 0.0) { // the end, interpolated linearly within the step
      const double s = x / (x - xn);
      c.duration = t + s * h;
      c.restitution = -(u + s * (un - u)) / v;
      return c;
    }
    x = xn;
    u = un;
    t += h;
    c.peak_overlap = std::max(c.peak_overlap, x);
  }
  throw std::runtime_error("liggghts_hertz_contact: the contact did not end");
}

double hertz_equivalent_kn(double y_eff, double reff, double meff, double v_c, double e,
                           double zeta, bool limit_force) {
  const double omega = linear_duration_factor(zeta, limit_force) /
                       liggghts_hertz_contact(y_eff, reff, meff, v_c, e).duration;
  return meff * omega * omega;
}

double linear_restitution(double zeta, bool limit_force) {
  return std::exp(log_restitution(zeta, limit_force));
}

double damping_ratio_for_restitution(double e, bool limit_force) {
  require(e > 0.0 && e <= 1.0, "coefficientRestitution must be in (0, 1], got " + number(e));
  const double target = std::log(e);
  if (!limit_force)
    return -target / std::sqrt(kPi * kPi + target * target);
  if (target == 0.0)
    return 0.0;
  // ln e(zeta) falls monotonically from 0 (zeta = 0) to -inf; bracket, then bisect to the last
  // bit.
  double lo = 0.0, hi = 1.0;
  while (log_restitution(hi, true) > target)
    hi *= 2.0;
  for (int k = 0; k < 200 && hi - lo > 1e-16 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (log_restitution(mid, true) > target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double linear_duration_factor(double zeta, bool limit_force) {
  if (!limit_force)
    return zeta < 1.0 ? kPi / std::sqrt(1.0 - zeta * zeta)
                      : std::numeric_limits<double>::infinity();
  if (zeta < 1.0)
    return 2.0 * std::acos(zeta) / std::sqrt(1.0 - zeta * zeta);
  if (zeta == 1.0)
    return 2.0;
  const double s = std::sqrt(zeta * zeta - 1.0);
  return -std::log1p(-2.0 * s / (zeta + s)) / s; // ln((zeta + s) / (zeta - s)) / s
}

double linear_contact_duration(double kn, double meff, double zeta, bool limit_force) {
  return linear_duration_factor(zeta, limit_force) / std::sqrt(kn / meff);
}

ContactCoefficients map_material(MaterialModel model, const MaterialProperties &p,
                                 const EquivalentSphere &a, const EquivalentSphere &b,
                                 const ContactCoefficients &switches) {
  require(model != MaterialModel::hooke_stiffness,
          "map_material: hooke/stiffness takes its coefficients as they are");
  require(std::isfinite(p.y_eff) && p.y_eff > 0.0,
          "youngsModulus: the effective modulus Y* = " + number(p.y_eff) + " must be > 0");
  require(std::isfinite(p.g_eff) && p.g_eff > 0.0,
          "poissonsRatio: the effective shear modulus G* = " + number(p.g_eff) + " must be > 0");
  require(std::isfinite(p.friction) && p.friction >= 0.0, "coefficientFriction must be >= 0");
  require(std::isfinite(p.v_char) && p.v_char > 0.0, "characteristicVelocity must be > 0");
  require(a.radius > 0.0 && a.mass > 0.0 && b.radius > 0.0 && b.mass > 0.0,
          "map_material: an equivalent sphere without positive radius and mass");
  const double reff = effective_radius(a.radius, b.radius);
  const double meff = effective_mass(a.mass, b.mass);
  const double zeta = damping_ratio_for_restitution(p.restitution, switches.limit_force);

  ContactCoefficients c = switches;
  double gammat_ratio = 1.0;
  if (model == MaterialModel::hooke) {
    c.kn = liggghts_hooke_kn(p.y_eff, reff, meff, p.v_char);
    c.kt = c.kn;
  } else {
    c.kn = hertz_equivalent_kn(p.y_eff, reff, meff, p.v_char, p.restitution, zeta,
                               switches.limit_force);
    c.kt = 6.0 * p.g_eff / p.y_eff * c.kn;
    gammat_ratio = 2.0 * std::sqrt(p.g_eff / p.y_eff);
  }
  const double gamman_abs = 2.0 * zeta * std::sqrt(c.kn * meff);
  const double gammat_abs = switches.tangential_damping ? gammat_ratio * gamman_abs : 0.0;
  c.gamman = switches.absolute_damping ? gamman_abs : gamman_abs / meff;
  c.gammat = switches.absolute_damping ? gammat_abs : gammat_abs / meff;
  c.mu = p.friction;
  return c;
}

double peak_overlap(double kn, double meff, double v) { return v * std::sqrt(meff / kn); }

double auto_epsilon(double kn, double meff, double v, double fraction) {
  return peak_overlap(kn, meff, v) / (2.0 * fraction);
}

} // namespace tri
