// Tests of material_mapping.h: LIGGGHTS's mixing and hooke stiffness against hand-computed
// values, the Hertz peak overlap and duration against a numerical integration of the Hertz
// law, the restitution of our linear spring-dashpot (with and without limitForce) against a
// numerical integration of the contact, its inverse, the full mapping for hooke and hertz
// (pairs and walls), and the epsilon-auto rule.
#include "model/material_mapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace {

constexpr double kPi = 3.14159265358979323846;

// Hand values (python, double precision) for Y = 1e8 Pa, nu = 0.3 on both sides, two cubes of
// side 4 mm (V = 6.4e-8 m^3) at density 2500, v_c = 1 m/s:
//   Y* = 1 / (2 (1 - 0.09) / 1e8) = 54945054.94505494
//   G* = 1 / (2 * 2 * 1.7 * 1.3 / 1e8) = 11312217.194570135
//   r = (3 V / (4 pi))^(1/3) = 0.002481401963597601, m = 1.6e-4
//   pair: reff = r / 2, meff = 8e-5
//   hooke kn = 16/15 sqrt(reff) Y* (15 meff / (16 sqrt(reff) Y*))^(1/5) = 17078.53901750499
//   delta_H = (15 meff / (16 Y* sqrt(reff)))^(2/5) = 6.844151830769698e-05
//   t_H = 2 * 1.4716375921623521 * delta_H = 0.00020144222241254945
//   hertz kn = meff (pi / t_H)^2 = 19457.575490915264
//   wall (reff = r, meff = m): hooke kn = 25886.224520626536
constexpr double kY = 1e8, kNu = 0.3, kV = 6.4e-8, kRho = 2500.0;
constexpr double kYeff = 54945054.94505494, kGeff = 11312217.194570135;
constexpr double kR = 0.002481401963597601, kM = 1.6e-4;
constexpr double kHookeKn = 17078.53901750499, kHertzKn = 19457.575490915264;
constexpr double kDeltaH = 6.844151830769698e-05, kTH = 0.00020144222241254945;
constexpr double kWallHookeKn = 25886.224520626536;

// m x'' = force(x, x') from x = 0, x' = v0 > 0 (approaching: x is the overlap) until the
// contact ends: x back to 0, or, with `clamp`, the force back to 0 while separating. RK4 with
// `steps` per nominal time `t_scale`; returns {exit speed / v0, duration, peak overlap}.
struct Integrated {
  double restitution, duration, peak;
};
Integrated integrate_contact(const std::function<double(double, double)> &force, double m,
                             double v0, double t_scale, bool clamp) {
  const double h = t_scale / 20000.0;
  double x = 0.0, v = v0, t = 0.0, peak = 0.0;
  auto acc = [&](double xx, double vv) { return -force(xx, vv) / m; };
  for (int k = 0; k < 10000000; ++k) {
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
    const double xn = x + h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    const double fn = force(xn, vn);
    if (xn <= 0.0 || (clamp && vn < 0.0 && fn <= 0.0)) {
      // linear interpolation of the end within the step
      const double f0 = clamp && vn < 0.0 && fn <= 0.0 ? force(x, v) : x;
      const double f1 = clamp && vn < 0.0 && fn <= 0.0 ? fn : xn;
      const double s = f0 / (f0 - f1);
      return {-(v + s * (vn - v)) / v0, t + s * h, peak};
    }
    x = xn;
    v = vn;
    t += h;
    peak = std::max(peak, x);
  }
  return {std::numeric_limits<double>::quiet_NaN(), t, peak};
}

TEST(MaterialMapping, LiggghtsMixingRules) {
  EXPECT_NEAR(tri::effective_youngs_modulus(kY, kNu, kY, kNu), kYeff, 1e-12 * kYeff);
  EXPECT_NEAR(tri::effective_shear_modulus(kY, kNu, kY, kNu), kGeff, 1e-12 * kGeff);
  // Different materials: 1 / ((1 - 0.25^2) / 2e7 + (1 - 0.4^2) / 5e8) = 20595201.318092883
  EXPECT_NEAR(tri::effective_youngs_modulus(2e7, 0.25, 5e8, 0.4), 20595201.318092883, 1e-4);
}

TEST(MaterialMapping, EquivalentSpheres) {
  const tri::EquivalentSphere s = tri::equivalent_sphere(kV, kRho);
  EXPECT_NEAR(s.radius, kR, 1e-15);
  EXPECT_DOUBLE_EQ(s.mass, kM);
  // mean of 1 and 3 (x 1e-9 m^3) is 2e-9: r = (3 * 2e-9 / (4 pi))^(1/3) = 7.815926417967720e-4
  const double volumes[] = {1e-9, 3e-9};
  const tri::EquivalentSphere mean = tri::equivalent_sphere_of_mean(volumes, 2, 1000.0);
  EXPECT_NEAR(mean.radius, 7.815926417967720e-4, 1e-16);
  EXPECT_DOUBLE_EQ(mean.mass, 2e-6);
  EXPECT_DOUBLE_EQ(tri::effective_radius(2.0, 6.0), 1.5);
  EXPECT_DOUBLE_EQ(tri::effective_radius(2.0, tri::wall_sphere().radius), 2.0);
}

TEST(MaterialMapping, HookeStiffnessIsHertzPeakOverlapSpring) {
  const double kn = tri::liggghts_hooke_kn(kYeff, kR / 2, kM / 2, 1.0);
  EXPECT_NEAR(kn, kHookeKn, 1e-10 * kHookeKn);
  EXPECT_NEAR(tri::hertz_peak_overlap(kYeff, kR / 2, kM / 2, 1.0), kDeltaH, 1e-12 * kDeltaH);
  // kn = meff v^2 / delta_H^2: the spring with Hertz's peak overlap
  EXPECT_NEAR(kn, (kM / 2) / (kDeltaH * kDeltaH), 1e-10 * kn);
  EXPECT_NEAR(tri::peak_overlap(kn, kM / 2, 1.0), kDeltaH, 1e-12 * kDeltaH);
}

TEST(MaterialMapping, HertzDurationAndPeakAgainstIntegration) {
  for (double v : {0.3, 1.0, 4.0}) {
    const double reff = kR / 2, meff = kM / 2;
    auto hertz = [&](double x, double) {
      return x > 0 ? 4.0 / 3.0 * kYeff * std::sqrt(reff) * std::pow(x, 1.5) : 0.0;
    };
    const double t = tri::hertz_contact_duration(kYeff, reff, meff, v);
    const Integrated r = integrate_contact(hertz, meff, v, t, false);
    EXPECT_NEAR(r.duration, t, 1e-6 * t) << "v " << v;
    EXPECT_NEAR(r.peak, tri::hertz_peak_overlap(kYeff, reff, meff, v), 1e-8 * r.peak);
    EXPECT_NEAR(r.restitution, 1.0, 1e-6);
  }
  EXPECT_NEAR(tri::hertz_contact_duration(kYeff, kR / 2, kM / 2, 1.0), kTH, 1e-12 * kTH);
  // The textbook 2.87 (meff^2 / (reff Y*^2 v))^(1/5) rounds the constant 2.868.
  const double textbook = 2.87 * std::pow(std::pow(kM / 2, 2) / (kR / 2 * kYeff * kYeff), 0.2);
  EXPECT_NEAR(tri::hertz_contact_duration(kYeff, kR / 2, kM / 2, 1.0), textbook, 1e-3 * textbook);
}

TEST(MaterialMapping, LiggghtsHertzContact) {
  // Undamped: Hertz's duration, peak overlap and full restitution.
  const tri::HertzContact h = tri::liggghts_hertz_contact(kYeff, kR / 2, kM / 2, 1.0, 1.0);
  EXPECT_NEAR(h.duration, kTH, 1e-8 * kTH);
  EXPECT_NEAR(h.restitution, 1.0, 1e-8);
  EXPECT_NEAR(h.peak_overlap, kDeltaH, 1e-8 * kDeltaH);
  // Damped as LIGGGHTS's hertz (beta from e = 0.5): against an independent integration
  // (integrate_contact, 4x finer than the kernel's), and LIGGGHTS's restitution is close to e.
  const double reff = kR / 2, meff = kM / 2, l = std::log(0.5);
  const double beta = l / std::sqrt(l * l + kPi * kPi);
  auto hertz = [&](double x, double u) {
    if (x <= 0.0)
      return 0.0;
    return 4.0 / 3.0 * kYeff * std::sqrt(reff) * std::pow(x, 1.5) -
           2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(2.0 * kYeff * std::sqrt(reff * x) * meff) *
               u;
  };
  const Integrated r = integrate_contact(hertz, meff, 1.0, kTH / 4.0, false);
  const tri::HertzContact d = tri::liggghts_hertz_contact(kYeff, reff, meff, 1.0, 0.5);
  EXPECT_NEAR(d.duration, r.duration, 1e-6 * r.duration); // the kernel's 20000 steps: ~1e-7
  EXPECT_NEAR(d.restitution, r.restitution, 2e-6);
  EXPECT_NEAR(d.restitution, 0.5, 0.01);
  EXPECT_GT(d.duration, kTH); // damping lengthens it
}

TEST(MaterialMapping, HertzEquivalentStiffnessMatchesDuration) {
  // Undamped: the spring with Hertz's duration, (pi / (2 I))^2 times the hooke kn.
  const double kn = tri::hertz_equivalent_kn(kYeff, kR / 2, kM / 2, 1.0, 1.0, 0.0, true);
  EXPECT_NEAR(kn, kHertzKn, 1e-7 * kHertzKn);
  EXPECT_NEAR(kPi * std::sqrt(kM / 2 / kn), kTH, 1e-7 * kTH);
  EXPECT_NEAR(kn / kHookeKn, 1.1392997651012087, 1e-7);
  // Damped, with and without limitForce: our contact (integrated) lasts as long as LIGGGHTS's.
  for (bool clamp : {true, false}) {
    const double zeta = tri::damping_ratio_for_restitution(0.5, clamp);
    const double k = tri::hertz_equivalent_kn(kYeff, kR / 2, kM / 2, 1.0, 0.5, zeta, clamp);
    const double meff = kM / 2, c = 2.0 * zeta * std::sqrt(k * meff);
    auto f = [&](double x, double v) { return k * x + c * v; };
    const Integrated r = integrate_contact(f, meff, 1.0, kTH, clamp);
    const double t_lh = tri::liggghts_hertz_contact(kYeff, kR / 2, meff, 1.0, 0.5).duration;
    EXPECT_NEAR(r.duration, t_lh, 1e-5 * t_lh) << "limitForce " << clamp;
    EXPECT_NEAR(r.restitution, 0.5, 2e-6) << "limitForce " << clamp;
  }
}

TEST(MaterialMapping, RestitutionOfLinearSpringDashpotAgainstIntegration) {
  const double kn = 2000.0, m = 8e-5, v0 = 0.5;
  for (bool clamp : {false, true})
    for (double zeta : {0.0, 0.05, 0.2154537619662468, 0.5, 0.8, 0.99, 1.0, 1.3, 3.0}) {
      if (!clamp && zeta >= 1.0) {
        EXPECT_EQ(tri::linear_restitution(zeta, false), 0.0);
        continue;
      }
      const double c = 2.0 * zeta * std::sqrt(kn * m);
      auto f = [&](double x, double v) { return kn * x + c * v; };
      const double t0 = kPi * std::sqrt(m / kn);
      const Integrated r = integrate_contact(f, m, v0, t0, clamp);
      EXPECT_NEAR(tri::linear_restitution(zeta, clamp), r.restitution, 2e-6)
          << "zeta " << zeta << " limitForce " << clamp;
      EXPECT_NEAR(tri::linear_contact_duration(kn, m, zeta, clamp), r.duration, 1e-5 * t0)
          << "zeta " << zeta << " limitForce " << clamp;
    }
  // Hand values: e(0.2154537619662468) = 0.5 without the clamp, 0.5502831696271157 with it.
  EXPECT_NEAR(tri::linear_restitution(0.2154537619662468, false), 0.5, 1e-14);
  EXPECT_NEAR(tri::linear_restitution(0.2154537619662468, true), 0.5502831696271157, 1e-14);
  EXPECT_NEAR(tri::linear_restitution(1.0, true), std::exp(-2.0), 1e-15);
  EXPECT_NEAR(tri::linear_restitution(1.0 - 1e-9, true), std::exp(-2.0), 1e-6);
  EXPECT_NEAR(tri::linear_restitution(1.0 + 1e-9, true), std::exp(-2.0), 1e-6);
}

TEST(MaterialMapping, DampingRatioInvertsRestitution) {
  // LIGGGHTS: |beta| = -ln e / sqrt(ln^2 e + pi^2) = 0.2154537619662468 for e = 0.5
  EXPECT_NEAR(tri::damping_ratio_for_restitution(0.5, false), 0.2154537619662468, 1e-15);
  EXPECT_NEAR(tri::damping_ratio_for_restitution(0.5, true), 0.2552756376486517, 1e-13);
  EXPECT_EQ(tri::damping_ratio_for_restitution(1.0, true), 0.0);
  EXPECT_EQ(tri::damping_ratio_for_restitution(1.0, false), 0.0);
  for (bool clamp : {false, true})
    for (double e : {0.01, 0.06, 0.1, 0.135, 0.2, 0.5, 0.9, 0.999}) {
      const double z = tri::damping_ratio_for_restitution(e, clamp);
      EXPECT_NEAR(tri::linear_restitution(z, clamp), e, 1e-12 * e) << "e " << e;
    }
  EXPECT_THROW(tri::damping_ratio_for_restitution(0.0, true), std::invalid_argument);
  EXPECT_THROW(tri::damping_ratio_for_restitution(1.01, false), std::invalid_argument);
}

tri::MaterialProperties material(double e, double mu) {
  tri::MaterialProperties p;
  p.y_eff = kYeff;
  p.g_eff = kGeff;
  p.restitution = e;
  p.friction = mu;
  p.v_char = 1.0;
  return p;
}

TEST(MaterialMapping, HookePairAsLiggghts) {
  const tri::EquivalentSphere s = tri::equivalent_sphere(kV, kRho);
  tri::ContactCoefficients sw;
  sw.limit_force = false; // LIGGGHTS's default: its damping formula then holds exactly
  const tri::ContactCoefficients c =
      tri::map_material(tri::MaterialModel::hooke, material(0.5, 0.4), s, s, sw);
  EXPECT_NEAR(c.kn, kHookeKn, 1e-10 * kHookeKn);
  EXPECT_EQ(c.kt, c.kn); // LIGGGHTS hooke: kt = kn
  // LIGGGHTS: gamman = sqrt(4 meff kn ln^2 e / (ln^2 e + pi^2)) kg/s; ours is that / meff.
  const double l = std::log(0.5);
  const double gamman_abs = std::sqrt(4.0 * kM / 2 * kHookeKn * l * l / (l * l + kPi * kPi));
  EXPECT_NEAR(c.gamman * kM / 2, gamman_abs, 1e-10 * gamman_abs);
  EXPECT_NEAR(c.gammat, c.gamman, 1e-12 * c.gamman); // LIGGGHTS hooke: gammat = gamman
  EXPECT_EQ(c.mu, 0.4);
  EXPECT_FALSE(c.limit_force);

  sw.absolute_damping = true;
  const tri::ContactCoefficients a =
      tri::map_material(tri::MaterialModel::hooke, material(0.5, 0.4), s, s, sw);
  EXPECT_NEAR(a.gamman, gamman_abs, 1e-10 * gamman_abs);
  sw.absolute_damping = false;
  sw.tangential_damping = false;
  EXPECT_EQ(tri::map_material(tri::MaterialModel::hooke, material(0.5, 0.4), s, s, sw).gammat, 0.0);
}

TEST(MaterialMapping, RestitutionIsExactWithLimitForce) {
  // Our default limitForce on: the damping is chosen so that the clamped contact restitutes e.
  const tri::EquivalentSphere s = tri::equivalent_sphere(kV, kRho);
  tri::ContactCoefficients sw;
  sw.limit_force = true;
  for (tri::MaterialModel model : {tri::MaterialModel::hooke, tri::MaterialModel::hertz})
    for (double e : {0.3, 0.5, 0.9}) {
      const tri::ContactCoefficients c = tri::map_material(model, material(e, 0.0), s, s, sw);
      const double meff = kM / 2, gamma = c.gamman * meff;
      auto f = [&](double x, double v) { return c.kn * x + gamma * v; };
      const Integrated r = integrate_contact(f, meff, 1.0, kPi * std::sqrt(meff / c.kn), true);
      EXPECT_NEAR(r.restitution, e, 2e-6) << tri::material_model_name(model) << " e " << e;
    }
}

TEST(MaterialMapping, HertzPairAndWall) {
  const tri::EquivalentSphere s = tri::equivalent_sphere(kV, kRho);
  tri::ContactCoefficients sw;
  const tri::ContactCoefficients c =
      tri::map_material(tri::MaterialModel::hertz, material(0.5, 0.3), s, s, sw);
  const double z0 = tri::damping_ratio_for_restitution(0.5, sw.limit_force);
  EXPECT_NEAR(c.kn, tri::hertz_equivalent_kn(kYeff, kR / 2, kM / 2, 1.0, 0.5, z0, sw.limit_force),
              1e-12 * c.kn);
  EXPECT_NEAR(tri::map_material(tri::MaterialModel::hertz, material(1.0, 0.3), s, s, sw).kn,
              kHertzKn, 1e-7 * kHertzKn);
  EXPECT_NEAR(c.kt, 6.0 * kGeff / kYeff * c.kn, 1e-12 * c.kt);
  EXPECT_NEAR(c.gammat / c.gamman, 2.0 * std::sqrt(kGeff / kYeff), 1e-12);
  // Wall: reff = r, meff = m.
  const tri::ContactCoefficients w =
      tri::map_material(tri::MaterialModel::hooke, material(0.5, 0.3), s, tri::wall_sphere(), sw);
  EXPECT_NEAR(w.kn, kWallHookeKn, 1e-10 * kWallHookeKn);
  const double z = tri::damping_ratio_for_restitution(0.5, sw.limit_force);
  EXPECT_NEAR(w.gamman * kM, 2.0 * z * std::sqrt(kWallHookeKn * kM), 1e-10);
}

TEST(MaterialMapping, BadPropertiesAreNamed) {
  const tri::EquivalentSphere s = tri::equivalent_sphere(kV, kRho);
  const tri::ContactCoefficients sw;
  auto message = [&](tri::MaterialProperties p) {
    try {
      tri::map_material(tri::MaterialModel::hooke, p, s, s, sw);
    } catch (const std::invalid_argument &e) {
      return std::string(e.what());
    }
    return std::string();
  };
  tri::MaterialProperties p = material(1.5, 0.3);
  EXPECT_NE(message(p).find("coefficientRestitution"), std::string::npos);
  p = material(0.5, -1.0);
  EXPECT_NE(message(p).find("coefficientFriction"), std::string::npos);
  p = material(0.5, 0.3);
  p.v_char = 0.0;
  EXPECT_NE(message(p).find("characteristicVelocity"), std::string::npos);
  p = material(0.5, 0.3);
  p.y_eff = 0.0;
  EXPECT_NE(message(p).find("youngsModulus"), std::string::npos);
  EXPECT_THROW(tri::map_material(tri::MaterialModel::hooke_stiffness, material(0.5, 0.3), s, s, sw),
               std::invalid_argument);
}

TEST(MaterialMapping, AutoEpsilon) {
  // kn 2000 N/m, meff 8e-5 kg, v 1 m/s: overlap sqrt(8e-5 / 2000) = 2e-4 m; half of 2 eps.
  EXPECT_NEAR(tri::peak_overlap(2000.0, 8e-5, 1.0), 2e-4, 1e-18);
  EXPECT_NEAR(tri::auto_epsilon(2000.0, 8e-5, 1.0), 2e-4, 1e-18);
  EXPECT_NEAR(tri::auto_epsilon(2000.0, 8e-5, 1.0, 0.25), 4e-4, 1e-18);
  // With the hooke kn the overlap is Hertz's peak overlap at v_c.
  EXPECT_NEAR(tri::auto_epsilon(kHookeKn, kM / 2, 1.0), kDeltaH, 1e-12 * kDeltaH);
}

} // namespace
