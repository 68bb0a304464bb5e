// tri::InteractionEngine: results and tallies independent of the thread count (bitwise),
// exceptions caught per task and reported for the lowest failing task, forces summed in
// (atom, partner) order whatever the order of contribution; and body_interaction's contract
// (pair symmetry, walls as rigidly moving bodies of infinite mass).
#include "body_pair_helpers.h"
#include "interaction/interaction_engine.h"

#include "body/random_rock.h"
#include "body/shape.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

using Eigen::Vector3d;

namespace {

constexpr double kEps = 1e-4;

tri::Shape rock(std::uint64_t seed) {
  tri::RockParameters p;
  p.ntri = 40;
  p.size = 0.004;
  p.seed = seed;
  return tri::make_shape("rock", tri::random_rock(p));
}

struct Particle {
  tri::TriangleSoA world;
  tri::Body body;
};

// A row of rocks, each touching the next (centres 3.9 mm apart, bounding diameter 4 mm).
std::vector<Particle> touching_row(int n) {
  std::vector<Particle> ps(n);
  for (int k = 0; k < n; ++k) {
    const tri::Shape s = rock(k + 1);
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(0.7 * k, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const Vector3d x(0.0036 * k, 0.0, 0.0);
    tri::transform_soa(s.soa, r, x, ps[k].world);
    ps[k].body.epsilon = kEps;
    ps[k].body.longest_edge = s.max_edge_length;
    ps[k].body.min_edge = s.min_edge_length;
    ps[k].body.state.x = x;
    ps[k].body.state.v = Vector3d(-0.01 * k, 0.002, 0.0);
    ps[k].body.state.omega = Vector3d(0.0, 0.0, 3.0 * k);
    ps[k].body.state.mass = 1e-4;
  }
  for (Particle &p : ps)
    p.body.triangles = &p.world;
  return ps;
}

tri::InteractionSettings settings() { return tri_test::settings(true); }

struct EngineRun {
  std::vector<tri::PairForceResult> results;
  tri::InteractionTally tally;
  std::vector<double> f, t; // n x 3
};

EngineRun evaluate_row(const std::vector<Particle> &ps, int threads) {
  tri::InteractionEngine engine;
  const tri::InteractionSettings s = settings();
  const int n = static_cast<int>(ps.size());
  std::vector<std::vector<double>> history(n - 1, std::vector<double>(tri::kHistoryDoubles, 0.0));
  engine.run(n - 1, threads, tri_test::body_pair_host([&](std::size_t k) {
               return tri_test::BodyPairTask{&ps[k].body, &ps[k + 1].body, &s, 1e-6,
                                             history[k].data(), {}};
             }));
  EXPECT_FALSE(engine.failed());
  EngineRun out;
  for (std::size_t k = 0; k < engine.size(); ++k)
    out.results.push_back(engine.result(k));
  out.tally = engine.tally();
  std::vector<double> f(3 * n, 0.0), t(3 * n, 0.0);
  std::vector<double *> frows(n), trows(n);
  for (int a = 0; a < n; ++a) {
    frows[a] = &f[3 * a];
    trows[a] = &t[3 * a];
  }
  // Named in reverse: apply() must still sum per atom in partner order.
  for (int k = n - 2; k >= 0; --k)
    engine.set_recipients(k, k, k + 1, k + 1, k);
  engine.apply(frows.data(), trows.data());
  out.f = f;
  out.t = t;
  return out;
}

} // namespace

TEST(InteractionEngine, ThreadCountChangesNothing) {
  const std::vector<Particle> ps = touching_row(12);
  const EngineRun one = evaluate_row(ps, 1), four = evaluate_row(ps, 4);
  ASSERT_EQ(one.results.size(), four.results.size());
  long long contacts = 0;
  for (std::size_t k = 0; k < one.results.size(); ++k) {
    EXPECT_EQ(one.results[k].force_a, four.results[k].force_a) << "task " << k;
    EXPECT_EQ(one.results[k].torque_b, four.results[k].torque_b) << "task " << k;
    contacts += one.results[k].contacts_after;
  }
  EXPECT_GT(contacts, 5); // the row touches: the comparison is not of zeros
  EXPECT_EQ(one.f, four.f);
  EXPECT_EQ(one.t, four.t);
  for (const tri::StatColumn &c : tri::stats_columns())
    EXPECT_EQ(c.value(one.tally), c.value(four.tally)) << c.name;
  EXPECT_EQ(one.tally.body_pairs_checked, 11);
  EXPECT_GT(one.tally.distance.triangle_pairs_tested, 0);
}

// Group sizes: kGroupTasks on one thread; on several, at least kGroupsPerThread groups a
// thread where the tasks allow, never below kMinGroupTasks nor above kGroupTasks. (One thread
// evaluating 11 tasks as one group and four as groups of 8 and 3 give the same results: above.)
TEST(InteractionEngine, GroupsShrinkWhenTasksAreFewForTheThreads) {
  using E = tri::InteractionEngine;
  EXPECT_EQ(E::tasks_per_group(5, 1), E::kGroupTasks);
  EXPECT_EQ(E::tasks_per_group(100000, 1), E::kGroupTasks);
  EXPECT_EQ(E::tasks_per_group(100000, 2), E::kGroupTasks);
  EXPECT_EQ(E::tasks_per_group(11, 4), E::kMinGroupTasks);
  EXPECT_EQ(E::tasks_per_group(0, 2), E::kMinGroupTasks);
  const long walls = 197; // a wall's tasks in the settled pile: 12 each, 17 groups, not 7
  EXPECT_EQ(E::tasks_per_group(walls, 2), walls / (E::kGroupsPerThread * 2));
  for (int threads = 2; threads <= 16; ++threads)
    for (long n = 0; n < 5000; n += 37) {
      const long g = E::tasks_per_group(n, threads);
      EXPECT_GE(g, E::kMinGroupTasks);
      EXPECT_LE(g, E::kGroupTasks);
      if (g > E::kMinGroupTasks) {
        EXPECT_GE((n + g - 1) / g, E::kGroupsPerThread * threads) << n << " tasks";
      }
    }
}

// The schedule on several threads (contiguous ranges, the rest taken from their backs): every
// task runs exactly once and lands in its own slot, for task counts below, at and above a
// group and ranges of very uneven cost (the last tasks spin, as a hopper's crowded pairs).
TEST(InteractionEngine, EveryTaskRunsOnceWhateverTheSchedule) {
  for (const int threads : {2, 3, 5})
    for (const std::size_t n : {0, 1, 7, 8, 9, 15, 16, 17, 31, 32, 33, 197, 1000}) {
      tri::InteractionEngine engine;
      std::vector<std::atomic<int>> runs(n);
      for (int repeat = 0; repeat < 2; ++repeat) { // the ranges are reset between runs
        for (std::atomic<int> &r : runs)
          r = 0;
        engine.run(n, threads, tri_test::finished_task_host([&](std::size_t k) {
          ++runs[k];
          volatile double spin = 0.0; // uneven cost: the last tenth of the tasks is slow
          for (int i = 0; k >= n - n / 10 && i < 20000; ++i)
            spin = spin + 1.0;
          tri::PairForceResult r;
          r.force_a = Vector3d(double(k), 0.0, 0.0);
          return r;
        }));
        ASSERT_EQ(engine.size(), n);
        for (std::size_t k = 0; k < n; ++k) {
          EXPECT_EQ(runs[k].load(), 1) << n << " tasks, " << threads << " threads, task " << k;
          EXPECT_EQ(engine.result(k).force_a.x(), double(k));
        }
      }
    }
}

TEST(InteractionEngine, AppliesInAtomThenPartnerOrder) {
  tri::InteractionEngine engine;
  // Values whose sum depends on the order: 1e16 + 1 - 1e16 is 0 one way, 1 another.
  const double force[3] = {1.0, 1e16, -1e16};
  engine.run(3, 1, tri_test::finished_task_host([&](std::size_t k) {
    tri::PairForceResult r;
    r.force_a = Vector3d(force[k], 0, 0);
    r.torque_b = Vector3d(0, force[k], 0);
    return r;
  }));
  const long long partner[3] = {7, 3, 9};
  for (std::size_t k = 0; k < 3; ++k)
    engine.set_recipients(k, 0, partner[k], 1, partner[k]);
  double f0[3] = {0, 0, 0}, t0[3] = {0, 0, 0}, f1[3] = {0, 0, 0}, t1[3] = {0, 0, 0};
  double *f[2] = {f0, f1}, *t[2] = {t0, t1};
  engine.apply(f, t);
  // Partner order 3, 7, 9: (1e16 + 1) - 1e16 = 0 in doubles. b takes -force_a and torque_b.
  EXPECT_EQ(f0[0], (1e16 + 1.0) - 1e16);
  EXPECT_EQ(f1[0], (-1e16 - 1.0) + 1e16);
  EXPECT_EQ(t1[1], (1e16 + 1.0) - 1e16);
  EXPECT_EQ(t0[1], 0.0);
  // A task without recipients adds nothing (a pair without contacts, a ghost's side).
  engine.set_recipients(1, -1, 0, -1, 0);
  f0[0] = 0.0;
  engine.apply(f, t);
  EXPECT_EQ(f0[0], 1.0 - 1e16);
}

TEST(InteractionEngine, ExceptionsAreCaughtAndTheLowestFailingTaskIsNamed) {
  for (const int threads : {1, 3}) {
    tri::InteractionEngine engine;
    std::vector<int> evaluated(20, 0);
    engine.run(20, threads, tri_test::finished_task_host([&](std::size_t k) {
      evaluated[k] = 1;
      if (k == 13 || k == 6)
        throw std::runtime_error("task " + std::to_string(k) + " broke");
      tri::PairForceResult r;
      r.contacts_after = 1;
      return r;
    }));
    ASSERT_TRUE(engine.failed());
    EXPECT_EQ(engine.failed_task(), 6u);
    EXPECT_EQ(engine.failure(), "task 6 broke");
    for (int k = 0; k < 20; ++k)
      EXPECT_EQ(evaluated[k], 1) << "task " << k; // the others still ran
    // A later run without failures clears the verdict.
    engine.run(2, threads, tri_test::finished_task_host([](std::size_t) {
      return tri::PairForceResult{};
    }));
    EXPECT_FALSE(engine.failed());
  }
}

TEST(BodyInteraction, SwappingTheBodiesNegatesTheForce) {
  const std::vector<Particle> ps = touching_row(2);
  const tri::InteractionSettings s = settings();
  tri::InteractionScratch scratch;
  tri::ContactStats stats;
  const tri::PairForceResult ab =
      tri_test::body_interaction_alone(ps[0].body, ps[1].body, s, 1e-6, nullptr, scratch, stats);
  const tri::PairForceResult ba =
      tri_test::body_interaction_alone(ps[1].body, ps[0].body, s, 1e-6, nullptr, scratch, stats);
  ASSERT_GT(ab.contacts_after, 0);
  EXPECT_LT((ab.force_a + ba.force_a).norm(), 1e-9 * ab.force_a.norm());
  EXPECT_LT((ab.torque_a - ba.torque_b).norm(), 1e-9 * (ab.torque_a.norm() + 1e-30));
}

// A cube resting on a wall patch that turns about a far axis: friction drags the cube along
// the wall's velocity at the contact point, omega x (p - axis), not at the patch's mean node
// velocity.
TEST(BodyInteraction, WallVelocityIsTheRigidMotionsAtTheContact) {
  tri::TriangleMesh cube;
  for (int i = 0; i < 8; ++i)
    cube.vertices.emplace_back(0.002 * (i & 1), 0.002 * ((i >> 1) & 1), 0.002 * ((i >> 2) & 1));
  cube.triangles = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
  const tri::Shape s = tri::make_shape("cube", cube);
  Particle p;
  const Vector3d x(0.0, 0.0, 0.001 + kEps); // bottom face 1 eps above z = 0: in contact
  tri::transform_soa(s.soa, Eigen::Matrix3d::Identity(), x, p.world);
  p.body.triangles = &p.world;
  p.body.epsilon = kEps;
  p.body.longest_edge = s.max_edge_length;
  p.body.min_edge = s.min_edge_length;
  p.body.state.x = x;
  p.body.state.mass = 1e-5;

  // The patch: two triangles of the plane z = 0 around the cube, far from the axis x = -0.1.
  tri::TriangleSoA patch;
  patch.resize(2);
  const Vector3d c0(-0.01, -0.01, 0), c1(0.01, -0.01, 0), c2(0.01, 0.01, 0), c3(-0.01, 0.01, 0);
  patch.set_vertex(0, 0, c0);
  patch.set_vertex(0, 1, c1);
  patch.set_vertex(0, 2, c2);
  patch.set_vertex(1, 0, c0);
  patch.set_vertex(1, 1, c2);
  patch.set_vertex(1, 2, c3);
  tri::Body wall;
  wall.triangles = &patch;
  wall.epsilon = kEps;
  wall.longest_edge = std::numeric_limits<double>::infinity();
  wall.min_edge = p.body.min_edge;
  // Spinning about the z axis through (-0.1, 0.3, 0) at 0.5 rad/s; centre of the motion at the
  // patch's mean, as fit_rigid_motion gives it.
  const Vector3d axis_point(-0.1, 0.3, 0), omega(0, 0, 0.5);
  wall.state.x = Vector3d::Zero();
  wall.state.v = omega.cross(wall.state.x - axis_point);
  wall.state.omega = omega;
  wall.state.mass = 0.0;

  tri::InteractionSettings st = settings();
  st.coefficients.tangential = tri::TangentialModel::no_history;
  tri::InteractionScratch scratch;
  tri::ContactStats stats;
  const tri::PairForceResult r =
      tri_test::body_interaction_alone(p.body, wall, st, 1e-6, nullptr, scratch, stats);
  ASSERT_GT(r.contacts_after, 0);
  ASSERT_GT(r.force_a.z(), 0.0); // pushed up
  const Vector3d surface = omega.cross(Vector3d(0, 0, 0) - axis_point); // under the cube
  const Vector3d drag(r.force_a.x(), r.force_a.y(), 0.0);
  ASSERT_GT(drag.norm(), 0.0);
  EXPECT_GT(drag.normalized().dot(surface.normalized()), 1.0 - 1e-9);
}

// apply() against a direct sum: each atom's sides (a: force_a, torque_a; b: -force_a,
// torque_b) in partner order, ties (partners repeated: two images) in task order, a before b;
// tasks without recipients add nothing. Values of many magnitudes, so any other order changes
// the bits; recipients named on any thread (the run's, in any order) or after it.
TEST(InteractionEngine, ApplySumsEachAtomInPartnerThenTaskOrder) {
  const int atoms = 300, tasks = 2000;
  std::vector<std::array<double, 9>> values;
  std::vector<std::array<long long, 4>> names; // a, partner of a, b, partner of b
  std::uint64_t state = 12345;
  auto next = [&]() { // a fixed sequence
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  for (int k = 0; k < tasks; ++k) {
    const bool none_a = next() < 0.1, none_b = next() < 0.2;
    names.push_back({none_a ? -1 : static_cast<long long>(next() * atoms),
                     static_cast<long long>(next() * 7),
                     none_b ? -1 : static_cast<long long>(next() * atoms),
                     static_cast<long long>(next() * 7)});
    std::array<double, 9> v;
    for (double &x : v)
      x = (next() - 0.5) * std::pow(10.0, static_cast<int>(next() * 30) - 15);
    values.push_back(v);
  }
  // The reference: every side as (atom, partner, task, side), stably sorted, summed in order.
  struct Side {
    long long atom, partner;
    int task, side;
  };
  std::vector<Side> sides;
  for (int k = 0; k < tasks; ++k)
    for (int side = 0; side < 2; ++side)
      if (names[k][2 * side] >= 0)
        sides.push_back({names[k][2 * side], names[k][2 * side + 1], k, side});
  std::stable_sort(sides.begin(), sides.end(), [](const Side &x, const Side &y) {
    return x.atom != y.atom ? x.atom < y.atom : x.partner < y.partner;
  });
  std::vector<double> expected(6 * atoms, 0.0);
  for (const Side &c : sides)
    for (int d = 0; d < 3; ++d) {
      const double f = values[c.task][d];
      expected[3 * c.atom + d] += c.side == 0 ? f : -f;
      expected[3 * atoms + 3 * c.atom + d] += values[c.task][3 + 3 * c.side + d];
    }
  for (const int threads : {1, 3}) {
    tri::InteractionEngine engine;
    engine.run(tasks, threads, tri_test::finished_task_host([&](std::size_t k) {
      tri::PairForceResult r;
      r.force_a = Vector3d(values[k][0], values[k][1], values[k][2]);
      r.torque_a = Vector3d(values[k][3], values[k][4], values[k][5]);
      r.torque_b = Vector3d(values[k][6], values[k][7], values[k][8]);
      if (k % 2 == 0) // half named on the run's threads, the rest after it, last first
        engine.set_recipients(k, static_cast<int>(names[k][0]), names[k][1],
                              static_cast<int>(names[k][2]), names[k][3]);
      return r;
    }));
    for (int k = tasks - 1; k >= 0; --k)
      if (k % 2 == 1)
        engine.set_recipients(k, static_cast<int>(names[k][0]), names[k][1],
                              static_cast<int>(names[k][2]), names[k][3]);
    std::vector<double> ft(6 * atoms, 0.0);
    std::vector<double *> frows(atoms), trows(atoms);
    for (int a = 0; a < atoms; ++a) {
      frows[a] = &ft[3 * a];
      trows[a] = &ft[3 * atoms + 3 * a];
    }
    engine.apply(frows.data(), trows.data());
    EXPECT_EQ(ft, expected) << threads << " threads";
  }
  EXPECT_NE(expected, std::vector<double>(expected.size(), 0.0));
}
