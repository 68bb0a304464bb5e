// Helpers shared by the tests of what body_interaction.h keeps between steps (the separating
// axis, test_separating_axis.cpp; the candidates, test_candidate_cache.cpp): rocks, one force
// law, brute force's contacts, and a bitwise comparison of two results.
#pragma once

#include "body_interaction.h"
#include "random_rock.h"
#include "shape.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tri_test {

inline tri::Shape rock(int ntri, std::uint64_t seed, double size = 0.004) {
  tri::RockParameters p;
  p.ntri = ntri;
  p.size = size;
  p.seed = seed;
  p.aspect_middle = 0.8;
  p.aspect_short = 0.6;
  return tri::make_shape("rock", tri::random_rock(p));
}

inline std::vector<tri::TriangleContact> brute_force_contacts(const tri::TriangleSoA &a, double ea,
                                                              const tri::TriangleSoA &b, double eb) {
  tri::ContactOptions opt;
  opt.kernel = tri::DistanceKernel::BruteForceScalar;
  opt.cull = false;
  std::vector<tri::TriangleContact> out;
  tri::ContactStats stats;
  tri::find_triangle_contacts(a, ea, b, eb, opt, out, stats);
  return out;
}

// tight: the two-frame cull (default); false: world boxes only. coherence: kept candidates'
// reach (body_interaction.h), 0 for none.
inline tri::InteractionSettings settings(bool tight, double coherence = 0.0) {
  tri::InteractionSettings s;
  s.distance.tight_cull = tight;
  s.coherence = coherence;
  s.coefficients.kn = 2000;
  s.coefficients.kt = 1000;
  s.coefficients.gamman = 20;
  s.coefficients.gammat = 10;
  s.coefficients.mu = 0.5;
  s.coefficients.limit_force = true;
  return s;
}

inline void expect_bitwise(const tri::PairForceResult &ref, const tri::PairForceResult &got,
                           const std::string &what) {
  ASSERT_EQ(ref.force_a, got.force_a) << what;
  ASSERT_EQ(ref.torque_a, got.torque_a) << what;
  ASSERT_EQ(ref.torque_b, got.torque_b) << what;
  ASSERT_EQ(ref.contacts_before, got.contacts_before) << what;
  ASSERT_EQ(ref.contacts_after, got.contacts_after) << what;
  ASSERT_EQ(ref.max_overlap, got.max_overlap) << what;
  ASSERT_EQ(ref.min_distance, got.min_distance) << what;
  ASSERT_EQ(ref.intersecting, got.intersecting) << what;
}

} // namespace tri_test
