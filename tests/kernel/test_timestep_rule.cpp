// Tests of timestep_rule.h: the contact time of the linear spring and the verdict at the
// edges of each threshold, including the deck that must stop (four 1 g particles, kn 5e4 N/m,
// dt 2e-4 s) and the adaptive case (dtmin tested for the error, dtmax for the warning).
#include "model/timestep_rule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

TEST(TimestepRule, ContactTime) {
  // meff of two 1 g particles 5e-4 kg, kn 5e4 N/m: pi sqrt(1e-8) = pi * 1e-4 s
  EXPECT_NEAR(tri::linear_contact_time(5e4, 5e-4), 3.14159265358979e-4, 1e-17);
  EXPECT_TRUE(std::isinf(tri::linear_contact_time(0.0, 1.0)));
}

tri::TimestepFigures figures(double dt, double tc) {
  tri::TimestepFigures f;
  f.dt_error = f.dt_warn = dt;
  f.contact_time = tc;
  f.epsilon = 1e-4;
  f.layers = 2e-4;
  return f;
}

TEST(TimestepRule, FourOneGramParticlesMustStop) {
  const double tc = tri::linear_contact_time(5e4, 5e-4);
  const tri::TimestepVerdict v = tri::judge_timestep(figures(2e-4, tc));
  EXPECT_TRUE(v.error);
  EXPECT_NEAR(v.error_fraction, 2e-4 / tc, 1e-15); // 0.6366: at velocity Verlet's limit
  EXPECT_FALSE(v.warn_contact);                    // the error says it all
}

TEST(TimestepRule, ThresholdEdges) {
  const double tc = 1e-3;
  EXPECT_FALSE(tri::judge_timestep(figures(0.99 * tri::kWarnFraction * tc, tc)).warn_contact);
  EXPECT_TRUE(tri::judge_timestep(figures(1.01 * tri::kWarnFraction * tc, tc)).warn_contact);
  EXPECT_FALSE(tri::judge_timestep(figures(1.01 * tri::kWarnFraction * tc, tc)).error);
  EXPECT_FALSE(tri::judge_timestep(figures(0.99 * tri::kErrorFraction * tc, tc)).error);
  EXPECT_TRUE(tri::judge_timestep(figures(0.99 * tri::kErrorFraction * tc, tc)).warn_contact);
  EXPECT_TRUE(tri::judge_timestep(figures(1.01 * tri::kErrorFraction * tc, tc)).error);

  tri::TimestepFigures f = figures(1e-6, tc);
  f.approach_speed = 0.99 * tri::kApproachFraction * f.epsilon / f.dt_warn;
  EXPECT_FALSE(tri::judge_timestep(f).warn_approach);
  f.approach_speed = 1.01 * tri::kApproachFraction * f.epsilon / f.dt_warn;
  EXPECT_TRUE(tri::judge_timestep(f).warn_approach);
  EXPECT_NEAR(tri::judge_timestep(f).approach_fraction, 1.01 * tri::kApproachFraction, 1e-12);

  f = figures(1e-6, tc);
  f.peak_overlap = 0.99 * f.layers;
  EXPECT_FALSE(tri::judge_timestep(f).warn_overlap);
  f.peak_overlap = 1.01 * f.layers;
  EXPECT_TRUE(tri::judge_timestep(f).warn_overlap);
}

TEST(TimestepRule, AdaptiveStepTestsItsBounds) {
  const double tc = 2e-6; // the 100 m/s deck: cubes of 0.16 g on kn 2e8 N/m
  tri::TimestepFigures f = figures(0.0, tc);
  f.dt_error = 1e-10; // dtmin
  f.dt_warn = 1e-5;   // dtmax
  tri::TimestepVerdict v = tri::judge_timestep(f);
  EXPECT_FALSE(v.error);
  EXPECT_TRUE(v.warn_contact);
  EXPECT_NEAR(v.contact_fraction, 5.0, 1e-12);
  f.dt_error = 1e-6; // dtmin half the contact time: even the smallest step cannot resolve it
  v = tri::judge_timestep(f);
  EXPECT_TRUE(v.error);
  EXPECT_NEAR(v.error_fraction, 0.5, 1e-12);
}

TEST(TimestepRule, NoContactTimeNoVerdict) {
  tri::TimestepFigures f = figures(1.0, std::numeric_limits<double>::infinity());
  const tri::TimestepVerdict v = tri::judge_timestep(f);
  EXPECT_FALSE(v.error || v.warn_contact || v.warn_approach || v.warn_overlap);
}

} // namespace
