// Particle-pair driver (particle_contacts.h): every kernel, with and without culling, in
// every parallel mode and for 1, 2 and 4 threads, reports the same triangle pairs as brute
// force, with distances within the hybrid tolerance; cases at 0.99 and 1.01 of 2 epsilon.
#include "contact/contact_reduction.h"
#include "distance/particle_contacts.h"
#include "test_particles.h"
#include "triangle_contact_search.h"

#include <gtest/gtest.h>
#include <omp.h>

using namespace tri;
using namespace tri_test;

namespace {

struct Scene {
  TriangleSoA a, b;
  double eps;
  std::string name;
};

// Particle b placed at `gap` from a along a seeded direction; a negative gap pushes b that
// far into a after placing it at contact distance eps.
Scene make_scene(int ntri, double size, double eps, double gap, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Scene s;
  s.eps = eps;
  s.a = to_soa(test_particle(ntri, size, seed));
  const TriangleSoA body = to_soa(test_particle(ntri, size, seed + 1000));
  const Eigen::Vector3d dir(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  s.b = place_at_gap(s.a, body, dir, gap > 0 ? gap : eps);
  if (gap <= 0) {
    TriangleSoA moved;
    transform_soa(s.b, Eigen::Matrix3d::Identity(), dir.normalized() * (gap - eps), moved);
    s.b = moved;
  }
  s.name = std::to_string(ntri) + " triangles, seed " + std::to_string(seed) + ", gap/eps " +
           std::to_string(gap / eps);
  return s;
}

std::vector<Scene> scenes() {
  std::vector<Scene> out;
  const double size = 4e-3, eps = 1e-4; // the DESIGN.md deck: 4 mm rocks, 0.1 mm layer
  std::uint64_t seed = 1;
  for (int ntri : {20, 40})
    for (double gap : {0.1, 0.5, 1.0, 1.5, 1.98, 2.02, -1.0})
      out.push_back(make_scene(ntri, size, eps, gap * eps, seed++));
  return out;
}

const std::vector<Scene> &all_scenes() {
  static const std::vector<Scene> s = scenes();
  return s;
}

std::vector<TriangleContact> contacts(const Scene &s, const ContactOptions &opt,
                                      ContactStats *stats = nullptr) {
  std::vector<TriangleContact> out;
  ContactStats local;
  find_triangle_contacts(s.a, s.eps, s.b, s.eps, opt, out, stats ? *stats : local);
  return out;
}

void expect_same_pairs(const std::vector<TriangleContact> &ref,
                       const std::vector<TriangleContact> &got, double tol,
                       const std::string &what) {
  ASSERT_EQ(ref.size(), got.size()) << what;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    ASSERT_EQ(ref[k].tri_a, got[k].tri_a) << what;
    ASSERT_EQ(ref[k].tri_b, got[k].tri_b) << what;
    ASSERT_NEAR(ref[k].distance, got[k].distance, tol) << what;
    ASSERT_EQ(ref[k].intersecting, got[k].intersecting) << what;
    ASSERT_NEAR(got[k].normal.norm(), 1.0, 1e-12) << what;
  }
}

} // namespace

TEST(ParticleContacts, EveryKernelFindsTheBruteForceContacts) {
  for (const Scene &s : all_scenes()) {
    ContactOptions ref_opt;
    ref_opt.kernel = DistanceKernel::BruteForceScalar;
    ref_opt.cull = false;
    const auto ref = contacts(s, ref_opt);
    for (auto kernel :
         {DistanceKernel::BruteForce, DistanceKernel::Hybrid, DistanceKernel::BatchedHybrid})
      for (bool cull : {false, true})
        for (int iterations : {4, 6, 8}) {
          ContactOptions opt;
          opt.kernel = kernel;
          opt.cull = cull;
          opt.newton_iterations = iterations;
          // The hybrid tolerance is 1e-4 eps; the requirement is 1e-3 eps.
          expect_same_pairs(ref, contacts(s, opt), 1e-4 * s.eps,
                            s.name + " kernel " + std::to_string(int(kernel)) +
                                (cull ? " culled" : "") + " iterations " +
                                std::to_string(iterations));
        }
  }
}

TEST(ParticleContacts, ContactExistsJustInsideTwoEpsilonAndNotJustOutside) {
  for (const Scene &s : all_scenes()) {
    if (s.name.find("gap/eps 1.98") == std::string::npos &&
        s.name.find("gap/eps 2.02") == std::string::npos)
      continue;
    const bool inside = s.name.find("gap/eps 1.98") != std::string::npos;
    for (auto kernel : {DistanceKernel::BruteForce, DistanceKernel::Hybrid,
                        DistanceKernel::BatchedHybrid, DistanceKernel::BruteForceScalar}) {
      ContactOptions opt;
      opt.kernel = kernel;
      const auto c = contacts(s, opt);
      EXPECT_EQ(!c.empty(), inside) << s.name;
      for (const auto &t : c)
        EXPECT_LT(t.distance, 2 * s.eps);
    }
  }
}

TEST(ParticleContacts, IdenticalForOneTwoAndFourThreadsInEveryMode) {
  const int saved = omp_get_max_threads();
  for (const Scene &s : all_scenes())
    for (auto kernel : {DistanceKernel::BruteForce, DistanceKernel::Hybrid,
                        DistanceKernel::BatchedHybrid, DistanceKernel::Penalty}) {
      ContactOptions opt;
      opt.kernel = kernel;
      opt.cull = false;
      omp_set_num_threads(1);
      const auto ref = contacts(s, opt);
      for (auto mode : {ContactParallelism::TrianglePairs, ContactParallelism::Batches})
        for (int threads : {1, 2, 4})
          for (int batch : {3, 8}) {
            omp_set_num_threads(threads);
            opt.parallel = mode;
            opt.batch_size = batch;
            if (kernel == DistanceKernel::BatchedHybrid && batch != 8)
              continue; // the batch is part of the batched kernel's definition
            const auto got = contacts(s, opt);
            ASSERT_EQ(ref.size(), got.size()) << s.name;
            for (std::size_t k = 0; k < ref.size(); ++k) {
              ASSERT_EQ(ref[k].tri_a, got[k].tri_a);
              ASSERT_EQ(ref[k].tri_b, got[k].tri_b);
              ASSERT_EQ(ref[k].distance, got[k].distance) << s.name << " threads " << threads;
              ASSERT_EQ(ref[k].point_a, got[k].point_a);
              ASSERT_EQ(ref[k].normal, got[k].normal);
            }
          }
      opt.parallel = ContactParallelism::None;
    }
  omp_set_num_threads(saved);
}

TEST(ParticleContacts, CullingNeverDropsAContactAndCountsAddUp) {
  std::mt19937_64 rng(61);
  for (int trial = 0; trial < 40; ++trial) {
    const double eps = uniform(rng, 0.02, 0.1) * 1e-3;
    const Scene s =
        make_scene(trial % 2 ? 40 : 20, 4e-3, eps, uniform(rng, -2, 2) * eps, 500 + trial);
    ContactOptions opt;
    opt.kernel = DistanceKernel::BruteForce;
    opt.cull = false;
    const auto all = contacts(s, opt);
    opt.cull = true;
    ContactStats stats;
    const auto culled = contacts(s, opt, &stats);
    expect_same_pairs(all, culled, 0.0, s.name);
    const int na = s.a.num_triangles(), nb = s.b.num_triangles();
    EXPECT_EQ(stats.triangle_pairs_tested + stats.triangle_pairs_culled, na * nb);
    EXPECT_EQ(stats.contacts, static_cast<long long>(culled.size()));
  }
}

TEST(ParticleContacts, StatsCountNewtonIterationsAndFallbacks) {
  ContactOptions opt;
  opt.cull = false;
  ContactStats stats;
  for (const Scene &s : all_scenes())
    contacts(s, opt, &stats);
  long long histogram = 0;
  for (long long h : stats.newton_histogram)
    histogram += h;
  EXPECT_EQ(histogram, stats.penalty_pairs);
  EXPECT_EQ(stats.penalty_pairs, stats.triangle_pairs_tested);
  EXPECT_GT(stats.fallbacks, 0);
  EXPECT_LT(stats.fallbacks, stats.penalty_pairs / 5);
}

// A wall has no layer of its own (its mesh is its contact surface): the particle's layer sets
// the tolerance. With a tolerance of 0 no penalty result could be certified and every wall
// pair within the layer would go to brute force.
TEST(ParticleContacts, AWallsZeroLayerTakesTheParticlesTolerance) {
  ContactOptions opt;
  EXPECT_EQ(certified_tolerance(opt, 2e-4, 0.0), opt.tolerance_ratio * 2e-4);
  EXPECT_EQ(certified_tolerance(opt, 0.0, 2e-4), opt.tolerance_ratio * 2e-4);
  EXPECT_EQ(certified_tolerance(opt, 1e-4, 3e-4), opt.tolerance_ratio * 1e-4);
  ContactOptions bf;
  bf.kernel = DistanceKernel::BruteForce;
  ContactStats stats;
  for (const Scene &s : all_scenes()) {
    std::vector<TriangleContact> ref, got;
    ContactStats unused;
    find_triangle_contacts(s.a, 2 * s.eps, s.b, 0.0, bf, ref, unused);
    find_triangle_contacts(s.a, 2 * s.eps, s.b, 0.0, opt, got, stats);
    expect_same_pairs(ref, got, opt.tolerance_ratio * 2 * s.eps, s.name);
  }
  EXPECT_GT(stats.penalty_pairs, 0);
  EXPECT_LT(stats.fallbacks, stats.penalty_pairs / 5);
}

TEST(ParticleContacts, PenetratingParticlesGiveIntersectingPairsWithFiniteNormals) {
  const Scene s = make_scene(40, 4e-3, 1e-4, -1e-4, 77);
  const auto c = contacts(s, ContactOptions{});
  int intersecting = 0;
  for (const auto &t : c) {
    intersecting += t.intersecting;
    EXPECT_TRUE(t.normal.allFinite());
    EXPECT_GE(t.penetration_depth, 0.0);
  }
  EXPECT_GT(intersecting, 0);
}

TEST(ParticleContacts, RejectsBadOptions) {
  const Scene &s = all_scenes().front();
  ContactOptions opt;
  opt.newton_iterations = 9;
  EXPECT_THROW(contacts(s, opt), std::invalid_argument);
  opt.newton_iterations = 4;
  opt.batch_size = 0;
  EXPECT_THROW(contacts(s, opt), std::invalid_argument);
}

// The tight cull (two frames and face planes) only removes pairs farther than the cutoff, and
// each pair's result does not depend on its neighbours in the list: the contacts of every
// kernel are bitwise those of the world-box cull (the batched hybrid decides per batch, so
// there only the pairs and the distances within its tolerance), with fewer pairs tested.
TEST(ParticleContacts, TightCullGivesTheBoxCullsContactsWithFewerPairs) {
  std::mt19937_64 rng(62);
  long long tested_tight = 0, tested_boxes = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const double eps = uniform(rng, 0.02, 0.1) * 1e-3;
    const Scene s =
        make_scene(trial % 2 ? 40 : 20, 4e-3, eps, uniform(rng, -1.5, 2.5) * eps, 900 + trial);
    for (auto kernel :
         {DistanceKernel::BruteForce, DistanceKernel::Hybrid, DistanceKernel::BatchedHybrid}) {
      ContactOptions opt;
      opt.kernel = kernel;
      opt.tight_cull = false;
      ContactStats boxes_stats, tight_stats;
      const auto boxes = contacts(s, opt, &boxes_stats);
      opt.tight_cull = true;
      const auto tight = contacts(s, opt, &tight_stats);
      if (kernel == DistanceKernel::BatchedHybrid) {
        expect_same_pairs(boxes, tight, 1e-4 * s.eps, s.name);
      } else {
        ASSERT_EQ(boxes.size(), tight.size()) << s.name;
        for (std::size_t k = 0; k < boxes.size(); ++k) {
          ASSERT_EQ(boxes[k].tri_a, tight[k].tri_a) << s.name;
          ASSERT_EQ(boxes[k].tri_b, tight[k].tri_b) << s.name;
          ASSERT_EQ(boxes[k].distance, tight[k].distance) << s.name;
          ASSERT_EQ(boxes[k].point_a, tight[k].point_a) << s.name;
          ASSERT_EQ(boxes[k].normal, tight[k].normal) << s.name;
        }
      }
      ASSERT_LE(tight_stats.triangle_pairs_tested, boxes_stats.triangle_pairs_tested) << s.name;
      tested_tight += tight_stats.triangle_pairs_tested;
      tested_boxes += boxes_stats.triangle_pairs_tested;
      const int na = s.a.num_triangles(), nb = s.b.num_triangles();
      EXPECT_EQ(tight_stats.triangle_pairs_tested + tight_stats.triangle_pairs_culled, na * nb);
    }
  }
  EXPECT_LT(tested_tight, 0.85 * tested_boxes);
}

// `parallel` shares a list among threads only from kMinSharedPairs candidates on: a short one
// (a particle pair of small rocks) can be queued with other pairs' kernels, kept lower bounds
// skipping what they rule out, on any thread count, so `parallel triangles` is not slower than
// `parallel none` on a pile. Seen from outside: a short list whose kept bounds rule out every
// pair, queued, tests none of them in every mode; a long one in a shared mode runs at once
// and tests them all, with the contacts of ContactParallelism::None.
TEST(ParticleContacts, OnlyLongListsAreSharedAmongThreads) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(2);
  const Scene &s = all_scenes().front(); // 20 triangles each: 400 pairs in all
  std::vector<TrianglePairIndex> all;
  for (int i = 0; i < s.a.num_triangles(); ++i)
    for (int j = 0; j < s.b.num_triangles(); ++j)
      all.push_back({i, j});
  ASSERT_GE(static_cast<int>(all.size()), kMinSharedPairs);
  const std::vector<double> ruled_out(all.size(), 1.0); // kept bounds far beyond the cutoff
  for (auto mode :
       {ContactParallelism::None, ContactParallelism::TrianglePairs, ContactParallelism::Batches})
    for (int count : {kMinSharedPairs - 1, kMinSharedPairs}) {
      ContactOptions opt;
      opt.parallel = mode;
      const bool shared = mode != ContactParallelism::None && count >= kMinSharedPairs;
      EXPECT_EQ(shares_among_threads(opt, count), shared);
      EXPECT_EQ(can_queue_candidates(opt, count), !shared);
      opt.kernel = DistanceKernel::BatchedHybrid;
      EXPECT_FALSE(can_queue_candidates(opt, count)); // its batches decide: never queued
      opt.kernel = DistanceKernel::Hybrid;
      ContactStats stats;
      if (shared) {
        ContactWorkspace ws;
        distances_among_candidates(s.a, s.eps, s.b, s.eps, opt, all.data(), count, stats, ws);
      } else {
        HybridJob job = queue_candidates(s.a, s.eps, s.b, s.eps, opt, all.data(), count, stats,
                                         ruled_out.data(), 0.5);
        std::vector<TrianglePairDistance> results(static_cast<std::size_t>(count));
        job.out = results.data();
        hybrid_distances_jobs(&job, 1, stats);
      }
      EXPECT_EQ(stats.triangle_pairs_tested, shared ? count : 0)
          << "mode " << static_cast<int>(mode) << ", " << count << " candidates";
      // Without bounds every mode finds None's contacts, bit for bit.
      ContactOptions none;
      ContactWorkspace ws_none, ws_mode;
      ContactStats st_none, st_mode;
      std::vector<TriangleContact> ref, got;
      contacts_among_candidates(s.a, s.eps, s.b, s.eps, none, all.data(), count, ref, st_none,
                                ws_none);
      contacts_among_candidates(s.a, s.eps, s.b, s.eps, opt, all.data(), count, got, st_mode,
                                ws_mode);
      ASSERT_EQ(ref.size(), got.size());
      for (std::size_t k = 0; k < ref.size(); ++k) {
        EXPECT_EQ(ref[k].distance, got[k].distance);
        EXPECT_EQ(ref[k].point_a, got[k].point_a);
      }
    }
  omp_set_num_threads(saved);
}

// The two ways to a body pair's kernel results (header): at once, and queued with the other
// scenes' jobs in one run (as the interaction engine runs a group's): bitwise the same results
// on every candidate, and the same counts.
TEST(ParticleContacts, QueuedCandidatesGiveTheResultsOfARunAtOnce) {
  const std::vector<Scene> &scenes = all_scenes();
  ContactOptions opt;
  std::vector<ContactWorkspace> found(scenes.size());
  std::vector<HybridJob> jobs;
  std::vector<std::vector<TrianglePairDistance>> queued(scenes.size());
  ContactStats queued_stats, at_once_stats;
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const Scene &s = scenes[k];
    const int count = find_candidate_pairs(s.a, s.b, 2 * s.eps, opt, found[k]);
    ASSERT_TRUE(can_queue_candidates(opt, count));
    jobs.push_back(
        queue_candidates(s.a, s.eps, s.b, s.eps, opt, found[k].pairs.data(), count, queued_stats));
    queued[k].resize(static_cast<std::size_t>(count));
    jobs.back().out = queued[k].data();
  }
  hybrid_distances_jobs(jobs.data(), static_cast<int>(jobs.size()), queued_stats);
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    const Scene &s = scenes[k];
    ContactWorkspace ws;
    const int count = jobs[k].count;
    distances_among_candidates(s.a, s.eps, s.b, s.eps, opt, found[k].pairs.data(), count,
                               at_once_stats, ws);
    for (int p = 0; p < count; ++p) {
      const TrianglePairDistance &x = ws.results[p], &y = queued[k][p];
      EXPECT_TRUE(x.distance == y.distance && x.lower_bound == y.lower_bound &&
                  x.point_a == y.point_a && x.point_b == y.point_b && x.normal == y.normal &&
                  x.intersecting == y.intersecting)
          << s.name << ", candidate " << p;
    }
    EXPECT_EQ(count_triangle_contacts(ws.results.data(), count, 2 * s.eps),
              count_triangle_contacts(queued[k].data(), count, 2 * s.eps))
        << s.name;
  }
  EXPECT_EQ(queued_stats.triangle_pairs_tested, at_once_stats.triangle_pairs_tested);
  EXPECT_EQ(queued_stats.triangle_pairs_culled, at_once_stats.triangle_pairs_culled);
}

// The pair loop reduces the kernel's results in place (reduce_kernel_results) instead of the
// TriangleContacts contacts_from_results would copy out of them: the contact points must be
// bitwise the same, for every scene (touching, intersecting, apart) and with a surface lift
// (where results beyond the cutoff would otherwise count).
TEST(ParticleContacts, ReducingKernelResultsInPlaceEqualsReducingTheirContacts) {
  for (const Scene &s : all_scenes())
    for (double lift : {0.0, 0.5}) {
      ContactOptions opt;
      ContactWorkspace ws;
      ContactStats stats;
      std::vector<TriangleContact> list;
      const int count = find_candidate_pairs(s.a, s.b, 3 * s.eps, opt, ws);
      contacts_among_candidates(s.a, s.eps, s.b, s.eps, opt, ws.pairs.data(), count, list, stats,
                                ws);
      ReductionParams params;
      params.link_length = recommended_link_length(1e-3, 1e-3, s.eps, s.eps);
      params.distance_tolerance = certified_tolerance(opt, s.eps, s.eps);
      params.surface_lift = lift * s.eps;
      ReductionWorkspace work_list, work_results;
      std::vector<ContactPoint> from_list, in_place;
      reduce_contacts(list.data(), static_cast<int>(list.size()), s.a, s.eps, s.b, s.eps, params,
                      work_list, from_list);
      reduce_kernel_results(ws.pairs.data(), ws.results.data(), count, 2 * s.eps, s.a, s.eps, s.b,
                            s.eps, params, work_results, in_place);
      ASSERT_EQ(from_list.size(), in_place.size()) << s.name;
      for (std::size_t k = 0; k < in_place.size(); ++k) {
        const ContactPoint &x = from_list[k], &y = in_place[k];
        EXPECT_TRUE(x.point == y.point && x.normal == y.normal &&
                    x.damping_point == y.damping_point &&
                    x.patch_second_moment == y.patch_second_moment)
            << s.name;
        const double xs[] = {x.overlap,    x.energy_overlap,    x.min_distance,
                             x.patch_area, x.patch_mean_radius, x.face_weight};
        const double ys[] = {y.overlap,    y.energy_overlap,    y.min_distance,
                             y.patch_area, y.patch_mean_radius, y.face_weight};
        for (int f = 0; f < 6; ++f)
          EXPECT_EQ(xs[f], ys[f]) << s.name << ", value " << f;
        EXPECT_TRUE(x.num_merged == y.num_merged && x.intersecting == y.intersecting &&
                    x.tri_a == y.tri_a && x.tri_b == y.tri_b)
            << s.name;
      }
    }
}
