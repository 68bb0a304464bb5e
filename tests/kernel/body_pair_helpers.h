// Helpers shared by the tests of body_interaction.h and what it keeps between steps (the
// separating axis, test_separating_axis.cpp; the candidates, test_candidate_cache.cpp): one
// body pair evaluated alone (the direct path that the engine's queued one must match bit for
// bit), engine hosts, rocks, one force law, brute force's contacts, and a bitwise comparison of
// two results.
#pragma once

#include "body/random_rock.h"
#include "body/shape.h"
#include "distance/distance_kernels.h"
#include "interaction/body_interaction.h"
#include "test_particles.h"
#include "triangle_contact_search.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <variant>
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
  find_triangle_contacts(a, ea, b, eb, opt, out, stats);
  return out;
}

// A body pair that proven_apart has not proven apart, evaluated alone: planned, its kernel
// request (if any) run at once as one job, and finished. `contacts` (optional): the triangle
// contacts of that job (none where the plan gave the result itself).
inline tri::PairForceResult body_interaction_not_apart(
    const tri::Body &a, const tri::Body &b, const tri::InteractionSettings &s, double dt,
    double *history, tri::InteractionScratch &scratch, tri::ContactStats &stats,
    tri::SeparationCache cache = {}, std::vector<tri::TriangleContact> *contacts = nullptr) {
  if (contacts)
    contacts->clear();
  tri::PairPlan plan = tri::plan_body_pair(a, b, s, dt, history, scratch, stats, cache);
  if (const tri::PairForceResult *done = std::get_if<tri::PairForceResult>(&plan))
    return *done;
  tri::KernelRequest &request = std::get<tri::KernelRequest>(plan);
  std::vector<tri::TrianglePairDistance> results(static_cast<std::size_t>(request.job.count));
  request.job.out = results.data();
  tri::hybrid_distances_jobs(&request.job, 1, stats);
  if (contacts) {
    tri::ContactStats ignored;
    tri::contacts_from_results(request.job.pairs, results.data(), request.job.count,
                               a.reach_epsilon(b) + b.reach_epsilon(a), *contacts, ignored);
  }
  return tri::finish_body_pair(a, b, s, dt, history, scratch, stats, cache, request,
                               results.data());
}

// One body pair evaluated alone, the way a host does: apart_result where proven_apart says so,
// else as above.
inline tri::PairForceResult
body_interaction_alone(const tri::Body &a, const tri::Body &b, const tri::InteractionSettings &s,
                       double dt, double *history, tri::InteractionScratch &scratch,
                       tri::ContactStats &stats, tri::SeparationCache cache = {},
                       std::vector<tri::TriangleContact> *contacts = nullptr) {
  if (tri::proven_apart(a, b, s, cache)) {
    if (contacts)
      contacts->clear();
    return tri::apart_result(a, b, s, dt, history, scratch, stats);
  }
  return body_interaction_not_apart(a, b, s, dt, history, scratch, stats, cache, contacts);
}

// An engine host (interaction_engine.h) for body pairs: pair(k) gives task k's BodyPairTask,
// and each task goes as body_interaction_alone's, its kernel queued by the engine.
struct BodyPairTask {
  const tri::Body *a, *b;
  const tri::InteractionSettings *settings;
  double dt;
  double *history;
  tri::SeparationCache cache;
};
template <class Pair> struct BodyPairHost {
  Pair pair;
  tri::PairPlan plan(std::size_t k, int, tri::InteractionScratch &scratch,
                     tri::ContactStats &stats) {
    const BodyPairTask t = pair(k);
    if (tri::proven_apart(*t.a, *t.b, *t.settings, t.cache))
      return tri::apart_result(*t.a, *t.b, *t.settings, t.dt, t.history, scratch, stats);
    return tri::plan_body_pair(*t.a, *t.b, *t.settings, t.dt, t.history, scratch, stats, t.cache);
  }
  tri::PairForceResult finish(std::size_t k, const tri::KernelRequest &request,
                              const tri::TrianglePairDistance *results,
                              tri::InteractionScratch &scratch, tri::ContactStats &stats) {
    const BodyPairTask t = pair(k);
    return tri::finish_body_pair(*t.a, *t.b, *t.settings, t.dt, t.history, scratch, stats, t.cache,
                                 request, results);
  }
  void complete(std::size_t, tri::PairForceResult &) {}
};
template <class Pair> BodyPairHost<Pair> body_pair_host(Pair pair) { return {pair}; }

// An engine host whose tasks finish at their plan with result(k): for the engine's own
// contract (schedule, errors, sums), without bodies.
template <class Result> struct FinishedTaskHost {
  Result result;
  tri::PairPlan plan(std::size_t k, int, tri::InteractionScratch &, tri::ContactStats &) {
    return result(k);
  }
  tri::PairForceResult finish(std::size_t, const tri::KernelRequest &,
                              const tri::TrianglePairDistance *, tri::InteractionScratch &,
                              tri::ContactStats &) {
    return {}; // never asked: no plan requests the kernel
  }
  void complete(std::size_t, tri::PairForceResult &) {}
};
template <class Result> FinishedTaskHost<Result> finished_task_host(Result result) {
  return {result};
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

// Two rocks on a path through contact, for the tests that run many steps: rock a at a fixed
// centre turning about axis_a, rock b at `d` along `dir` (plus a sideways sweep) turning about
// axis_b; the directions drawn from `seed`. at() writes both world-frame meshes and fills the
// bodies: rigid poses (with their shapes as frames), epsilon, mass 1e-4 kg, edges, omega.
struct RockPairPath {
  tri::Shape sa, sb;
  Eigen::Vector3d axis_a, axis_b, dir, side;

  RockPairPath(tri::Shape a, tri::Shape b, std::uint64_t seed) : sa(std::move(a)), sb(std::move(b)) {
    std::mt19937_64 rng(seed);
    auto u = [&rng] { return uniform(rng, -1, 1); };
    axis_a = Eigen::Vector3d(u(), u(), 1).normalized();
    axis_b = Eigen::Vector3d(1, u(), u()).normalized();
    dir = Eigen::Vector3d(u(), u(), u()).normalized();
    side = dir.unitOrthogonal();
  }

  // Angles turned so far (rad) and spin rates (rad/s) of a and b; sweep: b's sideways offset (m).
  void at(const Eigen::Vector3d &xa, double d, double sweep, double angle_a, double angle_b,
          double omega_a, double omega_b, double eps, tri::TriangleSoA &wa, tri::TriangleSoA &wb,
          tri::Body &a, tri::Body &b) const {
    a = tri::Body{};
    b = tri::Body{};
    a.pose.x = xa;
    b.pose.x = xa + d * dir + sweep * side;
    a.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(angle_a, axis_a));
    b.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(angle_b, axis_b));
    a.pose.radius = sa.bounding_radius;
    b.pose.radius = sb.bounding_radius;
    a.pose.frame = &sa;
    b.pose.frame = &sb;
    tri::transform_soa(sa.soa, a.pose.q.toRotationMatrix(), a.pose.x, wa);
    tri::transform_soa(sb.soa, b.pose.q.toRotationMatrix(), b.pose.x, wb);
    a.triangles = &wa;
    b.triangles = &wb;
    for (tri::Body *p : {&a, &b}) {
      p->epsilon = eps;
      p->state.mass = 1e-4;
      p->state.x = p->pose.x;
    }
    a.longest_edge = sa.max_edge_length;
    a.min_edge = sa.min_edge_length;
    b.longest_edge = sb.max_edge_length;
    b.min_edge = sb.min_edge_length;
    a.state.omega = omega_a * axis_a;
    b.state.omega = omega_b * axis_b;
  }
};

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

// Two tangential histories, bit for bit.
inline void expect_same_history(const double *ref, const double *got, const std::string &what) {
  for (int k = 0; k < tri::kHistoryDoubles; ++k)
    ASSERT_EQ(ref[k], got[k]) << what << ", history value " << k;
}

// A search's triangle contacts are exactly brute force's pairs, in the same order.
inline void expect_brute_force_pairs(const tri::TriangleSoA &a, const tri::TriangleSoA &b,
                                     double eps, const std::vector<tri::TriangleContact> &found,
                                     const std::string &what) {
  const auto bf = brute_force_contacts(a, eps, b, eps);
  ASSERT_EQ(bf.size(), found.size()) << what;
  for (std::size_t k = 0; k < bf.size(); ++k) {
    ASSERT_EQ(bf[k].tri_a, found[k].tri_a) << what;
    ASSERT_EQ(bf[k].tri_b, found[k].tri_b) << what;
  }
}

} // namespace tri_test
