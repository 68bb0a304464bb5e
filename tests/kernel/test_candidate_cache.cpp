// Kept triangle-pair candidates and kept gaps (candidate_cache.h): the motion bound at the edge
// of its reach, and over moving, rotating particle pairs and a rock bouncing on a wall patch,
// step after step, bitwise the result of the search without anything kept, with brute force's
// contacts, while the kept candidates and gaps do replace most searches.
#include "body_pair_helpers.h"
#include "distance/candidate_cache.h"
#include "interaction/interaction_engine.h"
#include "test_particles.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

using namespace tri;
using namespace tri_test;
using Eigen::Vector3d;

namespace {

// Moves `t` (a body of radius r about x) by a translation d and a rotation by `angle`, then
// asks whether candidates kept at the old pose with `reach` still cover it.
bool covers_after(double dx, double angle, double r, double reach) {
  const Shape s = rock(20, 7);
  RigidPose before, after;
  before.x = Vector3d(0.3, -0.2, 0.1);
  before.q = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()));
  before.radius = after.radius = r;
  after.x = before.x + dx * Vector3d(2, -1, 2).normalized();
  after.q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, Vector3d(-1, 1, 0.5).normalized())) *
            before.q;
  TriangleSoA wa, wb;
  transform_soa(s.soa, before.q.toRotationMatrix(), before.x, wa);
  RigidPose other;
  other.x = Vector3d(0.3, -0.2, 0.1 + 0.0041);
  other.radius = r;
  transform_soa(s.soa, Eigen::Matrix3d::Identity(), other.x, wb);
  CandidateCache cache;
  const TrianglePairIndex pairs[1] = {{0, 0}};
  cache.keep(&before, wa, &other, wb, 2e-4, reach, pairs, 1);
  transform_soa(s.soa, after.q.toRotationMatrix(), after.x, wa);
  return cache.covers(&after, wa, &other, wb, 2e-4);
}

// Two rocks that meet and part again (pair 0..3: 20 or 40 triangles each), and what a test
// keeps for them: the histories of a reference and of the tested evaluation, the kept axis,
// scratch, candidates and world triangles.
struct MeetingPair {
  RockPairPath path;
  double h_ref[kHistoryDoubles] = {}, h_got[kHistoryDoubles] = {}, axis[3] = {0, 0, 0};
  InteractionScratch scratch_ref, scratch_got;
  CandidateCache cache;
  TriangleSoA wa, wb;
  explicit MeetingPair(int pair)
      : path(rock(pair % 2 ? 40 : 20, 11 + pair), rock(pair / 2 ? 40 : 20, 21 + pair),
             700 + pair) {}
  // The bodies at time t in [0, 1]: centre distance 4.6 -> 2.6 -> 4.6 mm with a sideways sweep,
  // slow spins: a few um a step over 2000 steps; both carried by `drift` (m) on the way.
  void at(double t, double eps, Body &a, Body &b, const Vector3d &drift = Vector3d::Zero()) {
    const double d = 0.0026 + 0.002 * std::abs(std::cos(M_PI * t));
    path.at(Vector3d(0.01, -0.02, 0.03) + t * drift, d, 0.0008 * std::sin(5 * t), 1.5 * t, -2.0 * t,
            1.5, -2.0, eps, wa, wb, a, b);
  }
};

} // namespace

// D = |dx| + 2 sin(angle / 2) r: just inside the reach the list covers, just outside it does
// not; a different cutoff, radius or shape never reuses it.
TEST(CandidateCache, MotionBoundAtTheEdgeOfTheReach) {
  const double r = 0.002, reach = 1e-5;
  EXPECT_TRUE(covers_after(0.0, 0.0, r, reach));
  EXPECT_TRUE(covers_after(0.99 * reach, 0.0, r, reach));
  EXPECT_FALSE(covers_after(1.01 * reach, 0.0, r, reach));
  const double angle = 2.0 * std::asin(reach / (2.0 * r)); // chord = reach
  EXPECT_TRUE(covers_after(0.0, 0.99 * angle, r, reach));
  EXPECT_FALSE(covers_after(0.0, 1.01 * angle, r, reach));
  EXPECT_TRUE(covers_after(0.49 * reach, 0.49 * angle, r, reach));
  EXPECT_FALSE(covers_after(0.51 * reach, 0.51 * angle, r, reach));
  EXPECT_FALSE(covers_after(std::numeric_limits<double>::quiet_NaN(), 0.0, r, reach));

  const Shape s = rock(20, 7);
  TriangleSoA w;
  transform_soa(s.soa, Eigen::Matrix3d::Identity(), Vector3d::Zero(), w);
  RigidPose p;
  p.radius = s.bounding_radius;
  CandidateCache cache;
  EXPECT_FALSE(cache.covers(&p, w, &p, w, 2e-4)); // nothing kept yet
  cache.keep(&p, w, &p, w, 2e-4, 1e-5, nullptr, 0);
  EXPECT_TRUE(cache.covers(&p, w, &p, w, 2e-4));
  EXPECT_FALSE(cache.covers(&p, w, &p, w, 3e-4)); // another cutoff
  RigidPose bigger = p;
  bigger.radius *= 2;
  EXPECT_FALSE(cache.covers(&bigger, w, &p, w, 2e-4));
  RigidPose other_shape = p;
  other_shape.frame = &s.soa; // another particle under the same tag
  EXPECT_FALSE(cache.covers(&other_shape, w, &p, w, 2e-4));
  EXPECT_FALSE(cache.covers(&p, w, nullptr, w, 2e-4)); // a wall where a particle was
  RigidPose undescribed; // radius 0: a host that set no pose gets no reuse
  cache.keep(&undescribed, w, &p, w, 2e-4, 1e-5, nullptr, 0);
  EXPECT_FALSE(cache.covers(&undescribed, w, &p, w, 2e-4));
}

// Per-pair bounds (candidate_cache.h): a kept pair whose lower bound lies beyond the cutoff by
// more than the motion since its reference pose is skipped; rebase() moves the bounds to the
// new pose (a pair that ran takes its result's bound, a skipped one loses the motion), so a
// pair is skipped until the motion since it last ran could have closed its margin, and never
// once its bound is unknown (a kept list without results) or the motion is unbounded.
TEST(CandidateCache, KeptPairsAreSkippedWhileTheMotionCannotBringThemWithinTheCutoff) {
  const double cutoff = 2e-4, reach = 1e-4, r = 0.002;
  const Shape s = rock(20, 7);
  TriangleSoA wa, wb;
  RigidPose pa, pb;
  pa.radius = pb.radius = r;
  pb.x = Vector3d(0.0, 0.0, 0.004);
  transform_soa(s.soa, Eigen::Matrix3d::Identity(), pa.x, wa);
  transform_soa(s.soa, Eigen::Matrix3d::Identity(), pb.x, wb);
  const TrianglePairIndex pairs[4] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};
  TrianglePairDistance results[4];
  const double lower[4] = {0.5 * cutoff, cutoff + 0.2 * reach, cutoff + 0.6 * reach,
                           cutoff + 2.0 * reach}; // the last: beyond the list's reach
  for (int k = 0; k < 4; ++k)
    results[k].lower_bound = lower[k];
  CandidateCache cache;
  cache.keep(&pa, wa, &pb, wb, cutoff, reach, pairs, 4, results);
  ASSERT_EQ(cache.count(), 3);
  auto skipped = [&](double skip) {
    std::vector<int> out;
    for (int k = 0; k < cache.count(); ++k)
      if (cache.lower_bounds()[k] >= skip)
        out.push_back(k);
    return out;
  };
  // No motion: only the rounding slack; pairs 1 and 2 are beyond the cutoff.
  double skip = cache.skip_from(&pa, wa, &pb, wb, cutoff);
  EXPECT_GT(skip, cutoff);
  EXPECT_LT(skip, cutoff * (1 + 1e-6));
  EXPECT_EQ(skipped(skip), (std::vector<int>{1, 2}));
  // a moves 0.3 reach towards b: pair 1 (0.2 reach beyond) may now be within the cutoff.
  RigidPose moved = pa;
  moved.x.z() += 0.3 * reach;
  skip = cache.skip_from(&moved, wa, &pb, wb, cutoff);
  EXPECT_NEAR(skip, cutoff + 0.3 * reach, 1e-7 * cutoff); // slack: 1e-9 of the coordinates
  EXPECT_EQ(skipped(skip), (std::vector<int>{2}));
  // The kernel ran on pairs 0 and 1 (new bounds below), skipped pair 2: its bound loses the
  // 0.3 reach, the others take their results'.
  results[0].distance = 0.45 * cutoff; // ran
  results[0].lower_bound = 0.4 * cutoff;
  results[1].distance = cutoff + 0.3 * reach; // ran
  results[1].lower_bound = cutoff + 0.25 * reach;
  results[2].distance = std::numeric_limits<double>::infinity(); // skipped, as the kernel marks it
  results[2].lower_bound = std::numeric_limits<double>::quiet_NaN(); // not read
  cache.rebase(&moved, wa, &pb, wb, results);
  EXPECT_EQ(cache.lower_bounds()[0], 0.4 * cutoff);
  EXPECT_EQ(cache.lower_bounds()[1], cutoff + 0.25 * reach);
  EXPECT_NEAR(cache.lower_bounds()[2], cutoff + 0.3 * reach, 1e-7 * cutoff);
  // From the new reference pose, a further 0.2 reach: pair 1 (0.25 beyond) and pair 2 (0.3
  // beyond) are still skipped; 0.28 reach: pair 1 runs, pair 2 does not.
  RigidPose further = moved;
  further.x.z() += 0.2 * reach;
  ASSERT_TRUE(cache.covers(&further, wa, &pb, wb, cutoff)); // 0.5 reach since the keep
  EXPECT_EQ(skipped(cache.skip_from(&further, wa, &pb, wb, cutoff)), (std::vector<int>{1, 2}));
  further.x.z() = moved.x.z() + 0.28 * reach;
  EXPECT_EQ(skipped(cache.skip_from(&further, wa, &pb, wb, cutoff)), (std::vector<int>{2}));
  // A rotation counts with the radius: 2 sin(angle / 2) r = 0.28 reach, likewise.
  RigidPose turned = moved;
  turned.q = Eigen::Quaterniond(Eigen::AngleAxisd(2.0 * std::asin(0.14 * reach / r),
                                                  Vector3d(1, 2, 3).normalized()));
  EXPECT_EQ(skipped(cache.skip_from(&turned, wa, &pb, wb, cutoff)), (std::vector<int>{2}));
  // An unbounded motion (another radius) skips nothing and rebases nothing it cannot bound.
  RigidPose unknown = moved;
  unknown.radius = 2 * r;
  skip = cache.skip_from(&unknown, wa, &pb, wb, cutoff);
  EXPECT_EQ(skip, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(skipped(skip).empty());
  // A list kept without results knows no bound: every pair runs.
  cache.keep(&pa, wa, &pb, wb, cutoff, reach, pairs, 4);
  EXPECT_TRUE(skipped(cache.skip_from(&pa, wa, &pb, wb, cutoff)).empty());
}

// A wall patch is compared vertex by vertex: a moved vertex beyond the reach, or a patch that
// gained a triangle, is not covered; a kept gap proves the bodies apart only while the motion
// cannot have closed it.
TEST(CandidateCache, WallPatchByItsVerticesAndKeptGaps) {
  const Shape s = rock(20, 9);
  TriangleSoA particle, patch;
  transform_soa(s.soa, Eigen::Matrix3d::Identity(), Vector3d::Zero(), particle);
  patch.resize(1);
  patch.set_vertex(0, 0, Vector3d(-0.01, -0.01, -0.003));
  patch.set_vertex(0, 1, Vector3d(0.01, -0.01, -0.003));
  patch.set_vertex(0, 2, Vector3d(0.0, 0.01, -0.003));
  RigidPose p;
  p.radius = s.bounding_radius;
  CandidateCache cache;
  cache.keep(&p, particle, nullptr, patch, 2e-4, 1e-5, nullptr, 0);
  EXPECT_TRUE(cache.covers(&p, particle, nullptr, patch, 2e-4));
  TriangleSoA moved = patch;
  moved.set_vertex(0, 2, Vector3d(0.0, 0.01, -0.003 + 0.99e-5));
  EXPECT_TRUE(cache.covers(&p, particle, nullptr, moved, 2e-4));
  moved.set_vertex(0, 2, Vector3d(0.0, 0.01, -0.003 + 1.01e-5));
  EXPECT_FALSE(cache.covers(&p, particle, nullptr, moved, 2e-4));
  TriangleSoA grown = patch;
  grown.resize(2);
  for (int k = 0; k < 3; ++k)
    grown.set_vertex(1, k, patch.vertex(0, k));
  EXPECT_FALSE(cache.covers(&p, particle, nullptr, grown, 2e-4));

  // A gap of 5e-4 kept: apart for a cutoff of 2e-4 until the bodies have moved 3e-4.
  EXPECT_FALSE(cache.proves_apart(&p, particle, nullptr, patch, 2e-4)); // none kept yet
  cache.keep_gap(&p, particle, nullptr, patch, 5e-4);
  EXPECT_TRUE(cache.proves_apart(&p, particle, nullptr, patch, 2e-4));
  EXPECT_FALSE(cache.proves_apart(&p, particle, nullptr, patch, 6e-4));
  RigidPose q = p;
  q.x = Vector3d(0, 0, -2.9e-4);
  EXPECT_TRUE(cache.proves_apart(&q, particle, nullptr, patch, 2e-4));
  q.x = Vector3d(0, 0, -3.1e-4);
  EXPECT_FALSE(cache.proves_apart(&q, particle, nullptr, patch, 2e-4));

  // The same gap kept with its axis (particle towards wall: -z): only motion along the axis
  // closes it, with its sign; a turn by theta counts as 2 sin(theta / 2) r.
  cache.keep_gap(&p, particle, nullptr, patch, 5e-4, Vector3d(0, 0, -1));
  q = p;
  q.x = Vector3d(1e-3, -2e-3, 0); // sideways, far more than the gap
  EXPECT_TRUE(cache.proves_apart(&q, particle, nullptr, patch, 2e-4));
  q.x = Vector3d(1e-3, 0, -2.9e-4);
  EXPECT_TRUE(cache.proves_apart(&q, particle, nullptr, patch, 2e-4));
  q.x = Vector3d(0, 0, -3.1e-4);
  EXPECT_FALSE(cache.proves_apart(&q, particle, nullptr, patch, 2e-4));
  q.x = Vector3d(0, 0, 1e-3); // receding: the gap grows
  EXPECT_TRUE(cache.proves_apart(&q, particle, nullptr, patch, 1.4e-3));
  EXPECT_FALSE(cache.proves_apart(&q, particle, nullptr, patch, 1.6e-3));
  const double turn_ok = 2.0 * std::asin(2.9e-4 / (2.0 * p.radius)),
               turn_far = 2.0 * std::asin(3.1e-4 / (2.0 * p.radius));
  q.x = p.x;
  q.q = Eigen::Quaterniond(Eigen::AngleAxisd(turn_ok, Vector3d(1, 0, 0)));
  EXPECT_TRUE(cache.proves_apart(&q, particle, nullptr, patch, 2e-4));
  q.q = Eigen::Quaterniond(Eigen::AngleAxisd(turn_far, Vector3d(1, 0, 0)));
  EXPECT_FALSE(cache.proves_apart(&q, particle, nullptr, patch, 2e-4));
  TriangleSoA raised = patch; // a wall vertex rising towards the particle closes the gap
  raised.set_vertex(0, 2, Vector3d(0.0, 0.01, -0.003 + 2.9e-4));
  EXPECT_TRUE(cache.proves_apart(&p, particle, nullptr, raised, 2e-4));
  raised.set_vertex(0, 2, Vector3d(0.0, 0.01, -0.003 + 3.1e-4));
  EXPECT_FALSE(cache.proves_apart(&p, particle, nullptr, raised, 2e-4));
  raised.set_vertex(0, 2, Vector3d(0.005, 0.01, -0.003)); // sliding within its plane
  EXPECT_TRUE(cache.proves_apart(&p, particle, nullptr, raised, 4.9e-4));
}

// Two rocks spinning and sliding past each other through contact (and intersecting) and apart,
// over many steps: with candidates and gaps kept (and the axis, as the styles keep it), every
// step bitwise the result of the plain search, its contacts brute force's; most steps reuse
// what was kept.
TEST(CandidateCache, KeptCandidatesChangeNothingOnMovingRotatingPairs) {
  const double eps = 1e-4, dt = 1e-5;
  long long kept_steps = 0, separated = 0, touching = 0, searched = 0, listed = 0, ran = 0;
  for (int pair = 0; pair < 4; ++pair) {
    MeetingPair m(pair);
    const int steps = 2000;
    for (int step = 0; step < steps; ++step) {
      Body a, b;
      m.at(double(step) / steps, eps, a, b);
      ContactStats st_ref, st_got;
      const PairForceResult ref =
          body_interaction_alone(a, b, settings(true), dt, m.h_ref, m.scratch_ref, st_ref);
      std::vector<TriangleContact> found;
      const PairForceResult got =
          body_interaction_alone(a, b, settings(true, 0.25), dt, m.h_got, m.scratch_got, st_got,
                                 SeparationCache{m.axis, true, &m.cache}, &found);
      const std::string what = "pair " + std::to_string(pair) + " step " + std::to_string(step);
      ASSERT_NO_FATAL_FAILURE(expect_bitwise(ref, got, what));
      ASSERT_NO_FATAL_FAILURE(expect_same_history(m.h_ref, m.h_got, what));
      kept_steps += st_got.candidates_kept;
      if (st_got.candidates_kept > 0) { // the kept list's pairs, and those the kernel ran
        listed += m.cache.count();
        ran += st_got.triangle_pairs_tested;
      }
      separated += st_got.bodies_separated;
      touching += ref.contacts_after > 0;
      if (st_got.bodies_separated == 0) {
        ++searched;
        ASSERT_NO_FATAL_FAILURE(expect_brute_force_pairs(m.wa, m.wb, eps, found, what));
      } else {
        ASSERT_EQ(ref.contacts_after, 0) << what;
      }
    }
  }
  EXPECT_GT(touching, 1000);  // the trajectories do touch (1148) ...
  EXPECT_GT(kept_steps, 900); // ... and the kept candidates do most searches (1063 of 1232)
  EXPECT_GT(separated, 5000); // kept gaps and axes the rest (6768 of 8000 steps)
  // The kernel skips kept pairs the motion cannot have brought within the cutoff.
  std::printf("kept lists: %lld pairs listed, %lld run\n", listed, ran);
  EXPECT_LT(ran, 0.9 * listed); // 32717 of 38023: these bodies move a few um a step
}

// The same pairs carried 50 mm on the way, 25 um a step, both alike (a bed flowing as one):
// their own motions use up a kept list's reach (50 um) within a step, their relative motion
// does not, so the kept candidates still do most searches, and every step is bitwise the
// plain search.
TEST(CandidateCache, KeptCandidatesFollowAPairMovingTogether) {
  const double eps = 1e-4, dt = 1e-5;
  const Vector3d drift = 0.05 * Vector3d(1, -2, 2).normalized();
  long long kept_steps = 0, searched = 0;
  for (int pair = 0; pair < 4; ++pair) {
    MeetingPair m(pair);
    const int steps = 2000;
    for (int step = 0; step < steps; ++step) {
      Body a, b;
      m.at(double(step) / steps, eps, a, b, drift);
      ContactStats st_ref, st_got;
      const PairForceResult ref =
          body_interaction_alone(a, b, settings(true), dt, m.h_ref, m.scratch_ref, st_ref);
      const PairForceResult got =
          body_interaction_alone(a, b, settings(true, 0.25), dt, m.h_got, m.scratch_got, st_got,
                                 SeparationCache{m.axis, true, &m.cache});
      const std::string what = "pair " + std::to_string(pair) + " step " + std::to_string(step);
      ASSERT_NO_FATAL_FAILURE(expect_bitwise(ref, got, what));
      ASSERT_NO_FATAL_FAILURE(expect_same_history(m.h_ref, m.h_got, what));
      kept_steps += st_got.candidates_kept;
      searched += st_got.bodies_separated == 0;
    }
  }
  EXPECT_GT(searched, 1000);
  EXPECT_GT(kept_steps, 0.8 * searched); // as without the drift (1063 of 1232 there)
}

// A spinning rock sliding and bouncing on a patch of four wall triangles, one sloping: kept
// candidates and gaps against a wall (its vertices as its pose) change nothing.
TEST(CandidateCache, KeptCandidatesChangeNothingAgainstAWallPatch) {
  const double eps = 1e-4, dt = 1e-5;
  const Shape s = rock(40, 5);
  TriangleSoA patch;
  patch.resize(4);
  const Vector3d p[6] = {{-0.01, -0.01, 0}, {0.01, -0.01, 0}, {0.01, 0.01, 0},
                         {-0.01, 0.01, 0},  {0.02, -0.01, -0.005}, {0.02, 0.01, -0.005}};
  const int tris[4][3] = {{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  for (int t = 0; t < 4; ++t)
    for (int k = 0; k < 3; ++k)
      patch.set_vertex(t, k, p[tris[t][k]] + Vector3d(0.5, 0.5, 0.5));
  long long kept_steps = 0, touching = 0;
  double h_ref[kHistoryDoubles] = {}, h_got[kHistoryDoubles] = {}, axis[3] = {0, 0, 0};
  InteractionScratch scratch_ref, scratch_got;
  CandidateCache cache;
  TriangleSoA w;
  for (int step = 0; step < 1500; ++step) {
    const double t = step / 1500.0;
    RigidPose pose;
    pose.x = Vector3d(0.5 + 0.0085 * t, 0.5, 0.5 + 0.0009 + 0.0012 * std::abs(std::cos(M_PI * t)));
    pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(2.0 * t, Vector3d(1, 2, 3).normalized()));
    pose.radius = s.bounding_radius;
    transform_soa(s.soa, pose.q.toRotationMatrix(), pose.x, w);
    Body a, b;
    a.triangles = &w;
    a.pose = pose;
    a.epsilon = eps;
    a.longest_edge = s.max_edge_length;
    a.min_edge = s.min_edge_length;
    a.state.x = pose.x;
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
        body_interaction_alone(a, b, settings(true), dt, h_ref, scratch_ref, st_ref);
    const PairForceResult got =
        body_interaction_alone(a, b, settings(true, 0.05), dt, h_got, scratch_got, st_got,
                               SeparationCache{axis, true, &cache});
    const std::string what = "step " + std::to_string(step);
    ASSERT_NO_FATAL_FAILURE(expect_bitwise(ref, got, what));
    ASSERT_NO_FATAL_FAILURE(expect_same_history(h_ref, h_got, what));
    kept_steps += st_got.candidates_kept;
    touching += ref.contacts_after > 0;
  }
  EXPECT_GT(touching, 400);   // 522 of 1500 steps
  EXPECT_GT(kept_steps, 200); // 261
}

// The engine queues the distance kernel of every task served by its kept candidates or a
// search and runs a group's kernels together (interaction_engine.h). 24 rock pairs, each on its
// own path through contact, over 600 steps, evaluated by the engine on 1 and 2 threads and
// alone (body_interaction_alone: each kernel job run on its own) with caches of their own:
// bitwise the same forces, torques, histories and kept state at every step, and most contacts
// do go through queued kernels.
TEST(CandidateCache, EngineQueuedKernelsChangeNothing) {
  const double eps = 1e-4, dt = 1e-5;
  const int npairs = 24, steps = 600;
  std::vector<RockPairPath> paths;
  paths.reserve(npairs); // the poses name the shapes by address (RigidPose::frame)
  for (int p = 0; p < npairs; ++p)
    paths.emplace_back(rock(p % 2 ? 40 : 20, 31 + p), rock(p % 3 ? 20 : 40, 61 + p), 900 + p);
  // Per evaluation mode (direct, engine 1 thread, engine 2 threads): each pair's history, axis
  // and kept candidates.
  struct Kept {
    std::vector<std::vector<double>> history;
    std::vector<std::array<double, 3>> axis;
    std::vector<CandidateCache> caches;
  };
  std::vector<Kept> kept(3);
  for (Kept &k : kept) {
    k.history.assign(npairs, std::vector<double>(kHistoryDoubles, 0.0));
    k.axis.assign(npairs, {0.0, 0.0, 0.0});
    k.caches.resize(npairs);
  }
  const InteractionSettings s = settings(true, 0.25);
  std::vector<TriangleSoA> wa(npairs), wb(npairs);
  std::vector<Body> a(npairs), b(npairs);
  InteractionScratch direct_scratch;
  InteractionEngine engine;
  long long queued = 0, touching = 0;
  for (int step = 0; step < steps; ++step) {
    const double t = double(step) / steps;
    for (int p = 0; p < npairs; ++p) {
      const double d = 0.0021 + 0.0012 * std::abs(std::cos(M_PI * (t + 0.04 * p)));
      paths[p].at(Vector3d(0.01 * p, -0.02, 0.03), d, 0.0006 * std::sin(5 * t + p),
                  1.2 * t + 0.3 * p, -1.7 * t, 1.2, -1.7, eps, wa[p], wb[p], a[p], b[p]);
    }
    auto task = [&](Kept &k, std::size_t p) {
      const SeparationCache cache{k.axis[p].data(), true, &k.caches[p]};
      return BodyPairTask{&a[p], &b[p], &s, dt, k.history[p].data(), cache};
    };
    std::vector<PairForceResult> direct(npairs);
    for (int p = 0; p < npairs; ++p) {
      ContactStats stats;
      const BodyPairTask t = task(kept[0], p);
      direct[p] =
          body_interaction_alone(*t.a, *t.b, s, dt, t.history, direct_scratch, stats, t.cache);
      touching += direct[p].contacts_after > 0;
    }
    for (int mode = 1; mode <= 2; ++mode) {
      engine.run(npairs, mode, body_pair_host([&](std::size_t p) { return task(kept[mode], p); }));
      ASSERT_FALSE(engine.failed()) << engine.failure();
      if (mode == 1)
        queued += engine.tally().distance.candidates_kept;
      for (int p = 0; p < npairs; ++p) {
        const std::string what = "mode " + std::to_string(mode) + " pair " + std::to_string(p) +
                                 " step " + std::to_string(step);
        expect_bitwise(direct[p], engine.result(p), what);
        ASSERT_EQ(kept[0].history[p], kept[mode].history[p]) << what;
        ASSERT_EQ(kept[0].axis[p], kept[mode].axis[p]) << what;
      }
    }
  }
  std::printf("touching %lld of %d, kept lists queued %lld\n", touching, npairs * steps, queued);
  EXPECT_GT(touching, 2000);
  EXPECT_GT(queued, 1500);
}

// The reach a search keeps its candidates with: the coherence's for slow bodies, what the
// relative motion covers in kCandidateSteps steps for fast ones, never beyond the cap, and the
// coherence's for a motion that is not finite.
TEST(CandidateCache, ReachFollowsTheRelativeMotion) {
  Body a, b;
  a.pose.radius = b.pose.radius = 0.002;
  const double cutoff = 2e-4, dt = 1e-5, coherence = 0.05;
  EXPECT_EQ(candidate_reach(a, b, coherence, cutoff, dt), coherence * cutoff);
  b.state.v = Vector3d(0.1, 0, 0); // 1 um a step
  EXPECT_DOUBLE_EQ(candidate_reach(a, b, coherence, cutoff, dt), kCandidateSteps * 1e-6);
  a.state.omega = Vector3d(0, 0, 100); // + 2 um a step at the radius
  EXPECT_DOUBLE_EQ(candidate_reach(a, b, coherence, cutoff, dt), kCandidateSteps * 3e-6);
  ASSERT_LT(kCandidateSteps * 3e-6, kCandidateReachCap * cutoff); // below the cap
  b.state.v = Vector3d(50, 0, 0);
  EXPECT_DOUBLE_EQ(candidate_reach(a, b, coherence, cutoff, dt), kCandidateReachCap * cutoff);
  b.state.v = Vector3d(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  EXPECT_EQ(candidate_reach(a, b, coherence, cutoff, dt), coherence * cutoff);
}

// rigid_motion_bound: no vertex of a rock moves farther than |dx| + 2 sin(theta / 2) r between
// two random poses, and the bound is nearly reached (a vertex at the bounding radius, turned
// about an axis across it).
TEST(CandidateCache, RigidMotionBoundHoldsForEveryVertex) {
  const Shape s = rock(40, 3);
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double tightest = 0.0;
  for (int k = 0; k < 2000; ++k) {
    RigidPose then, now;
    then.x = Vector3d(u(rng), u(rng), u(rng));
    then.q = Eigen::Quaterniond(Eigen::AngleAxisd(3.0 * u(rng), Vector3d(u(rng), u(rng), 1).normalized()));
    const double scale = std::pow(10.0, -6.0 + 5.0 * (u(rng) + 1.0) / 2.0); // small and large steps
    now.x = then.x + scale * Vector3d(u(rng), u(rng), u(rng));
    now.q = Eigen::Quaterniond(Eigen::AngleAxisd(scale * 1e3 * u(rng),
                                                 Vector3d(u(rng), 1, u(rng)).normalized())) * then.q;
    then.radius = now.radius = s.bounding_radius;
    then.frame = now.frame = &s.soa;
    const double bound = rigid_motion_bound(then, now);
    double moved = 0.0;
    for (std::size_t i = 0; i < s.soa.x.size(); ++i) {
      const Vector3d p(s.soa.x[i], s.soa.y[i], s.soa.z[i]);
      moved = std::max(moved, ((now.q * p + now.x) - (then.q * p + then.x)).norm());
    }
    ASSERT_LE(moved, bound * (1.0 + 1e-12) + 1e-15) << "pose pair " << k;
    tightest = std::max(tightest, moved / bound);
  }
  EXPECT_GT(tightest, 0.9);
  RigidPose other = RigidPose{};
  other.radius = s.bounding_radius; // another frame: no bound
  EXPECT_EQ(rigid_motion_bound(other, RigidPose{}), std::numeric_limits<double>::infinity());
}

// relative_motion_bound: between two random relative poses of two rocks (small and large
// steps, both moving), no vertex of one moves relative to a vertex of the other by more than the
// bound, whichever body moved; it is nearly reached; and a body of radius 0 bounds nothing.
TEST(CandidateCache, RelativeMotionBoundHoldsForEveryVertexPair) {
  const Shape sa = rock(20, 3), sb = rock(40, 5);
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto random_pose = [&](const Vector3d &centre, double spread) {
    RigidPose p;
    p.x = centre + spread * Vector3d(u(rng), u(rng), u(rng));
    p.q = Eigen::Quaterniond(
        Eigen::AngleAxisd(3.0 * u(rng), Vector3d(u(rng), u(rng), 1).normalized()));
    return p;
  };
  auto moved_pose = [&](const RigidPose &then, double scale) {
    RigidPose now = then;
    now.x = then.x + scale * Vector3d(u(rng), u(rng), u(rng));
    now.q = Eigen::Quaterniond(
                Eigen::AngleAxisd(scale * 1e3 * u(rng), Vector3d(u(rng), 1, u(rng)).normalized())) *
            then.q;
    return now;
  };
  auto world = [](const Shape &s, const RigidPose &p, std::size_t i) {
    return Vector3d(p.q * Vector3d(s.soa.x[i], s.soa.y[i], s.soa.z[i]) + p.x);
  };
  double tightest = 0.0;
  for (int k = 0; k < 500; ++k) {
    const double scale = std::pow(10.0, -6.0 + 4.0 * (u(rng) + 1.0) / 2.0);
    const RigidPose a0 = random_pose(Vector3d(0.3, -0.1, 0.2), 0.1);
    const RigidPose b0 = random_pose(a0.x, 0.004);
    const RigidPose a1 = moved_pose(a0, scale), b1 = moved_pose(b0, scale);
    const double bound = relative_motion_bound(relative_pose(a0, b0), relative_pose(a1, b1),
                                               sa.bounding_radius, sb.bounding_radius);
    double moved = 0.0;
    for (std::size_t i = 0; i < sa.soa.x.size(); ++i)
      for (std::size_t j = 0; j < sb.soa.x.size(); ++j) {
        const double then = (world(sb, b0, j) - world(sa, a0, i)).norm();
        const double now = (world(sb, b1, j) - world(sa, a1, i)).norm();
        moved = std::max(moved, std::abs(now - then));
      }
    ASSERT_LE(moved, bound * (1.0 + 1e-9) + 1e-15) << "pose pair " << k;
    tightest = std::max(tightest, moved / bound);
  }
  EXPECT_GT(tightest, 0.5);
  const RelativePose still{Vector3d(0.003, 0, 0), Eigen::Quaterniond::Identity()};
  EXPECT_EQ(relative_motion_bound(still, still, 0.0, 0.0), std::numeric_limits<double>::infinity());
  EXPECT_EQ(relative_motion_bound(still, still, 0.002, 0.0), 0.0);
}

// The travel proof (candidate_cache.h): a host keeps each particle's running motion sum and,
// before evaluating a pair, asks proves_apart_by_travel; where it holds, the host takes the
// zero result and touches nothing. Over moving, rotating rock pairs that meet and part again,
// that is bitwise what a full evaluation gives (result and history), every pair it passes over
// is at least the cutoff apart by brute force, and it passes over most of the apart steps.
// A new epoch, or a contact (clear_gap), ends the proof.
TEST(CandidateCache, TravelProofPassesOverOnlyPairsThatAreApart) {
  const double eps = 1e-4, dt = 1e-5, cutoff = 2.0 * eps;
  long long passed = 0, apart_steps = 0;
  for (int pair = 0; pair < 4; ++pair) {
    MeetingPair m(pair);
    Travel travel{0.0, 0.0, 1};
    RigidPose last_a, last_b;
    const int steps = 2000;
    for (int step = 0; step < steps; ++step) {
      Body a, b;
      m.at(double(step) / steps, eps, a, b);
      if (step > 0) { // the host's sums
        travel.a += rigid_motion_bound(last_a, a.pose);
        travel.b += rigid_motion_bound(last_b, b.pose);
      }
      last_a = a.pose;
      last_b = b.pose;
      const std::string what = "pair " + std::to_string(pair) + " step " + std::to_string(step);
      ContactStats st_ref, st_got;
      const PairForceResult ref =
          body_interaction_alone(a, b, settings(true), dt, m.h_ref, m.scratch_ref, st_ref);
      apart_steps += ref.contacts_after == 0;
      if (m.cache.proves_apart_by_travel(travel, cutoff)) {
        ++passed;
        ASSERT_NO_FATAL_FAILURE(expect_bitwise(ref, PairForceResult{}, what));
        ASSERT_NO_FATAL_FAILURE(expect_same_history(m.h_ref, m.h_got, what));
        std::vector<TrianglePairIndex> all;
        for (int i = 0; i < m.wa.num_triangles(); ++i)
          for (int j = 0; j < m.wb.num_triangles(); ++j)
            all.push_back({i, j});
        std::vector<TrianglePairDistance> out(all.size());
        brute_force_distances(m.wa, m.wb, all.data(), static_cast<int>(all.size()), out.data());
        for (const TrianglePairDistance &r : out)
          ASSERT_GE(r.distance, cutoff) << what;
        continue;
      }
      const PairForceResult got =
          body_interaction_alone(a, b, settings(true, 0.25), dt, m.h_got, m.scratch_got, st_got,
                                 SeparationCache{m.axis, true, &m.cache, travel});
      ASSERT_NO_FATAL_FAILURE(expect_bitwise(ref, got, what));
      ASSERT_NO_FATAL_FAILURE(expect_same_history(m.h_ref, m.h_got, what));
    }
    // Another epoch (the host renumbered its atoms): the kept proof no longer counts.
    EXPECT_FALSE(m.cache.proves_apart_by_travel(Travel{travel.a, travel.b, 2}, cutoff));
  }
  std::printf("travel proof: %lld of %lld apart steps passed over\n", passed, apart_steps);
  EXPECT_GT(passed, apart_steps / 2);

  // A contact drops the proof with the gap.
  CandidateCache cache;
  cache.keep_travel(Travel{1.0, 2.0, 5}, 1e-3, 0.1);
  EXPECT_TRUE(cache.proves_apart_by_travel(Travel{1.0002, 2.0003, 5}, 2e-4));
  EXPECT_FALSE(cache.proves_apart_by_travel(Travel{1.0005, 2.0004, 5}, 2e-4));
  EXPECT_FALSE(cache.proves_apart_by_travel(Travel{1.0, 2.0, 0}, 2e-4)); // no sums kept
  cache.clear_gap();
  EXPECT_FALSE(cache.proves_apart_by_travel(Travel{1.0, 2.0, 5}, 2e-4));
  cache.keep_travel(Travel{1.0, 2.0, 5}, std::numeric_limits<double>::quiet_NaN(), 0.1);
  EXPECT_FALSE(cache.proves_apart_by_travel(Travel{1.0, 2.0, 5}, 2e-4));
}
