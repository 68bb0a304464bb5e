// Separating axes (separating_axis.h) and the kept axis of body_interaction.h: the proven gap
// is never more than any triangle-pair distance, at scales 1e-6 to 1e3 and far from the origin;
// and over moving, rotating particle pairs and particle-wall pairs, step after step, a kept
// axis and the tight cull change nothing: the same contacts as brute force, and bitwise the
// same forces, torques and history as the search without either.
#include "body/random_rock.h"
#include "body/shape.h"
#include "body_pair_helpers.h"
#include "distance/separating_axis.h"
#include "interaction/body_interaction.h"
#include "test_particles.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <vector>

using namespace tri;
using namespace tri_test;
using Eigen::Vector3d;

TEST(SeparatingAxis, ProvenGapNeverExceedsATrianglePairDistance) {
  std::mt19937_64 rng(12);
  int separated = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const double scale = std::pow(10.0, uniform(rng, -6, 3));
    const Vector3d far(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    const Vector3d origin = far * scale * uniform(rng, 0, 1000); // far from the origin too
    TriangleSoA a, b, body;
    transform_soa(to_soa(test_particle(20, scale, 40 + trial)), random_rotation(rng), origin, a);
    transform_soa(to_soa(test_particle(20, scale, 90 + trial)), random_rotation(rng), origin, body);
    const Vector3d dir(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    b = place_at_gap(a, body, dir, uniform(rng, 0.01, 0.3) * scale);
    const double distance = particle_distance(a, b);
    for (int k = 0; k < 20; ++k) {
      Vector3d axis =
          k == 0 ? dir : Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
      axis = axis.normalized() * std::pow(10.0, uniform(rng, -3, 3)); // not unit
      const double gap = proven_gap(a, b, axis, 0.0);
      ASSERT_LE(gap, distance) << "trial " << trial << " scale " << scale;
      separated += gap > 0.0;
    }
  }
  EXPECT_GT(separated, 30); // the axes along the placement direction do prove a gap
}

TEST(SeparatingAxis, UnusableAxesProveNothing) {
  const TriangleSoA a = to_soa(test_particle(20, 1.0, 1));
  TriangleSoA b;
  transform_soa(a, Eigen::Matrix3d::Identity(), Vector3d(10, 0, 0), b);
  EXPECT_TRUE(separated_along(a, b, Vector3d(1, 0, 0), 1.0));
  EXPECT_FALSE(separated_along(a, b, Vector3d(-1, 0, 0), 1.0)); // the wrong way round
  EXPECT_FALSE(separated_along(a, b, Vector3d::Zero(), 1.0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(separated_along(a, b, Vector3d(nan, 0, 0), 1.0));
  EXPECT_FALSE(separated_along(a, TriangleSoA{}, Vector3d(1, 0, 0), 1.0));
  EXPECT_FALSE(separated_along(a, b, Vector3d(1, 0, 0), 100.0)); // gap below the cutoff
}

// Two rocks on a trajectory that brings them from apart into contact (also intersecting)
// and out again, both spinning fast, over many steps: with the kept axis and the tight cull
// (the default) every step gives bitwise the result of the plain box-culled search, and the
// contacts the search finds are brute force's.
TEST(SeparatingAxis, KeptAxisAndTightCullChangeNothingOnMovingRotatingPairs) {
  const double eps = 1e-4, dt = 1e-5;
  long long separated = 0, touching = 0, searched = 0;
  for (int pair = 0; pair < 4; ++pair) {
    const RockPairPath path(rock(pair % 2 ? 40 : 20, 11 + pair),
                            rock(pair / 2 ? 40 : 20, 21 + pair), 300 + pair);
    double h_ref[kHistoryDoubles] = {}, h_got[kHistoryDoubles] = {}, cache[3] = {0, 0, 0};
    InteractionScratch scratch_ref, scratch_got;
    TriangleSoA wa, wb;
    const int steps = 500;
    for (int step = 0; step < steps; ++step) {
      const double t = double(step) / steps;
      // centre distance 5.0 -> 2.4 -> 5.0 mm (bounding diameter 4 mm), with a sideways sweep
      const double d = 0.0024 + 0.0026 * std::abs(std::cos(M_PI * t));
      Body a, b;
      path.at(Vector3d(0.01, -0.02, 0.03), d, 0.0008 * std::sin(5 * t), 6.0 * t, -9.0 * t, 6.0,
              -9.0, eps, wa, wb, a, b);
      b.state.v = -0.38 * path.dir;
      ContactStats st_ref, st_got;
      const PairForceResult ref =
          body_interaction_alone(a, b, settings(false), dt, h_ref, scratch_ref, st_ref);
      std::vector<TriangleContact> found;
      const PairForceResult got =
          body_interaction_alone(a, b, settings(true), dt, h_got, scratch_got, st_got,
                                 SeparationCache{cache, true}, &found);
      const std::string what = "pair " + std::to_string(pair) + " step " + std::to_string(step);
      ASSERT_NO_FATAL_FAILURE(expect_bitwise(ref, got, what));
      ASSERT_NO_FATAL_FAILURE(expect_same_history(h_ref, h_got, what));
      separated += st_got.bodies_separated;
      touching += ref.contacts_after > 0;
      if (st_got.bodies_separated == 0) {
        ++searched;
        ASSERT_NO_FATAL_FAILURE(expect_brute_force_pairs(wa, wb, eps, found, what));
        ASSERT_LE(st_got.triangle_pairs_tested, st_ref.triangle_pairs_tested) << what;
      } else {
        ASSERT_EQ(ref.contacts_after, 0) << what;
        ASSERT_TRUE(brute_force_contacts(wa, eps, wb, eps).empty()) << what;
      }
    }
  }
  EXPECT_GT(separated, 1000); // the kept axis does the work where the rocks are apart ...
  EXPECT_GT(touching, 100);   // ... and the trajectories do touch
  EXPECT_GT(searched, 150);
}

// A spinning rock bouncing on a patch of wall triangles, body b of infinite mass: a floor of
// four triangles, one of them sloping down (an axis is kept), and a floor with a side wall that
// the rock also hits (no single axis separates it from that patch: the planes of the wall
// triangles prove it apart instead). Neither changes anything.
TEST(SeparatingAxis, KeptAxisAndWallPlanesChangeNothingAgainstAWallPatch) {
  for (int corner = 0; corner < 2; ++corner) {
    const double eps = 1e-4, dt = 1e-5;
    const Shape s = rock(40, 5);
    TriangleSoA patch;
    patch.resize(4);
    const double up = corner ? 0.01 : -0.005, out = corner ? 0.01 : 0.02;
    const Vector3d p[6] = {{-0.01, -0.01, 0}, {0.01, -0.01, 0}, {0.01, 0.01, 0},
                           {-0.01, 0.01, 0},  {out, -0.01, up}, {out, 0.01, up}};
    const int tris[4][3] = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
    for (int t = 0; t < 4; ++t)
      for (int k = 0; k < 3; ++k)
        patch.set_vertex(t, k, p[tris[t][k]] + Vector3d(0.5, 0.5, 0.5));
    long long separated = 0, touching = 0;
    double h_ref[kHistoryDoubles] = {}, h_got[kHistoryDoubles] = {}, cache[3] = {0, 0, 0};
    InteractionScratch scratch_ref, scratch_got;
    TriangleSoA w;
    for (int step = 0; step < 400; ++step) {
      const double t = step / 400.0;
      const Vector3d x =
          Vector3d(0.5 + 0.0085 * t, 0.5, 0.5 + 0.0008 + 0.003 * std::abs(std::cos(3 * M_PI * t)));
      transform_soa(s.soa,
                    Eigen::AngleAxisd(7.0 * t, Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
                    x, w);
      Body a, b;
      a.triangles = &w;
      a.epsilon = eps;
      a.longest_edge = s.max_edge_length;
      a.min_edge = s.min_edge_length;
      a.state.x = x;
      a.state.mass = 1e-4;
      a.state.v = Vector3d(0.6, 0, -0.3);
      b.triangles = &patch;
      b.epsilon = eps;
      b.longest_edge = std::numeric_limits<double>::infinity();
      b.min_edge = s.min_edge_length;
      b.state.x = Vector3d(0.5, 0.5, 0.5);
      b.state.mass = 0.0;
      ContactStats st_ref, st_got;
      const PairForceResult ref =
          body_interaction_alone(a, b, settings(false), dt, h_ref, scratch_ref, st_ref);
      std::vector<TriangleContact> found;
      const PairForceResult got =
          body_interaction_alone(a, b, settings(true), dt, h_got, scratch_got, st_got,
                                 SeparationCache{cache, true}, &found);
      const std::string what = "corner " + std::to_string(corner) + " step " + std::to_string(step);
      ASSERT_NO_FATAL_FAILURE(expect_bitwise(ref, got, what));
      ASSERT_NO_FATAL_FAILURE(expect_same_history(h_ref, h_got, what));
      separated += st_got.bodies_separated;
      touching += ref.contacts_after > 0;
    }
    EXPECT_GT(separated, 100) << "corner " << corner;
    EXPECT_GT(touching, 50) << "corner " << corner;
  }
}

// A read-only cache (LIGGGHTS's setup) is used but never written.
TEST(SeparatingAxis, ReadOnlyCacheIsNotWritten) {
  const Shape s = rock(20, 3);
  TriangleSoA wa, wb;
  transform_soa(s.soa, Eigen::Matrix3d::Identity(), Vector3d::Zero(), wa);
  transform_soa(s.soa, Eigen::Matrix3d::Identity(), Vector3d(0.0045, 0, 0), wb);
  Body a, b;
  a.triangles = &wa;
  b.triangles = &wb;
  for (Body *p : {&a, &b}) {
    p->epsilon = 1e-4;
    p->state.mass = 1e-4;
    p->longest_edge = s.max_edge_length;
    p->min_edge = s.min_edge_length;
  }
  b.state.x = Vector3d(0.0045, 0, 0);
  InteractionScratch scratch;
  ContactStats stats;
  double cache[3] = {0, 0, 0};
  body_interaction_alone(a, b, settings(true), 1e-5, nullptr, scratch, stats,
                         SeparationCache{cache, false});
  EXPECT_EQ(Vector3d(cache), Vector3d::Zero());
  body_interaction_alone(a, b, settings(true), 1e-5, nullptr, scratch, stats,
                         SeparationCache{cache, true});
  EXPECT_GT(Vector3d(cache).norm(), 0.99); // apart: an axis is kept
  EXPECT_EQ(stats.bodies_separated, 0);
  body_interaction_alone(a, b, settings(true), 1e-5, nullptr, scratch, stats,
                         SeparationCache{cache, true});
  EXPECT_EQ(stats.bodies_separated, 1); // and used
}

// A body's extent from its pose (body-frame vertices, quaternion, centre) is its world-frame
// vertices' extent to rounding, at scales 1e-6 to 1e3 and far from the origin.
TEST(SeparatingAxis, PosedExtentIsTheWorldExtent) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const double scale = std::pow(10.0, uniform(rng, -6, 3));
    const Shape s = rock(trial % 2 ? 40 : 20, 5 + trial, scale);
    const Vector3d x = Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)) *
                       scale * uniform(rng, 0, 1000);
    const Eigen::Quaterniond q(random_rotation(rng));
    TriangleSoA world;
    transform_soa(s.soa, q.toRotationMatrix(), x, world);
    const Vector3d n = Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1))
                           .normalized();
    const Extent w = soa_extent(world, n), p = posed_extent(s.soa, q, x, s.bounding_radius, n);
    ASSERT_GE(p.magnitude, w.magnitude);
    const double rounding = 1e-14 * p.magnitude;
    ASSERT_NEAR(p.lo, w.lo, rounding) << "trial " << trial;
    ASSERT_NEAR(p.hi, w.hi, rounding) << "trial " << trial;
  }
}

// What a host does that builds world-frame triangles only for pairs that need them (pair
// tri/gran): tri::proven_apart on bodies whose triangles are not built (empty here), from
// their poses; apart_result for the pairs it proves apart, body_interaction (with the
// triangles) for the others. Over moving, rotating rock pairs, bitwise the result of
// body_interaction on world triangles without poses, and most apart steps are proven from the
// poses alone.
TEST(SeparatingAxis, PosesAloneProveWhatTheWorldTrianglesProve) {
  const double eps = 1e-4, dt = 1e-5;
  long long by_pose = 0, apart_steps = 0;
  for (int pair = 0; pair < 4; ++pair) {
    const RockPairPath path(rock(pair % 2 ? 40 : 20, 31 + pair),
                            rock(pair / 2 ? 40 : 20, 41 + pair), 500 + pair);
    double h_ref[kHistoryDoubles] = {}, h_got[kHistoryDoubles] = {};
    double axis_ref[3] = {0, 0, 0}, axis_got[3] = {0, 0, 0};
    CandidateCache kept_ref, kept_got;
    InteractionScratch scratch_ref, scratch_got;
    TriangleSoA wa, wb;
    const TriangleSoA not_built;
    for (int step = 0; step < 500; ++step) {
      const double t = step / 500.0;
      const double d = 0.0024 + 0.0026 * std::abs(std::cos(M_PI * t));
      Body a, b;
      path.at(Vector3d(0.3, -0.2, 0.1), d, 0.0008 * std::sin(5 * t), 6.0 * t, -9.0 * t, 6.0,
              -9.0, eps, wa, wb, a, b);
      b.state.v = -0.38 * path.dir;
      const InteractionSettings s = settings(true, 0.05);
      ContactStats st_ref, st_got;
      const PairForceResult ref = body_interaction_alone(
          a, b, s, dt, h_ref, scratch_ref, st_ref, SeparationCache{axis_ref, true, &kept_ref});
      Body pa = a, pb = b;
      pa.frame = &path.sa.soa;
      pb.frame = &path.sb.soa;
      pa.triangles = pb.triangles = &not_built;
      const SeparationCache cache{axis_got, true, &kept_got};
      PairForceResult got;
      if (proven_apart(pa, pb, s, cache)) {
        ++by_pose;
        got = apart_result(pa, pb, s, dt, h_got, scratch_got, st_got);
      } else {
        pa.triangles = &wa;
        pb.triangles = &wb;
        got = body_interaction_not_apart(pa, pb, s, dt, h_got, scratch_got, st_got,
                                         SeparationCache{axis_got, true, &kept_got});
      }
      const std::string what = "pair " + std::to_string(pair) + " step " + std::to_string(step);
      ASSERT_NO_FATAL_FAILURE(expect_bitwise(ref, got, what));
      ASSERT_NO_FATAL_FAILURE(expect_same_history(h_ref, h_got, what));
      apart_steps += ref.contacts_after == 0;
    }
  }
  EXPECT_GT(by_pose, apart_steps * 9 / 10); // measured: 1649 of 1694
  EXPECT_GT(apart_steps, 1000);
}
