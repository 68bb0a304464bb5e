// Kernels on pair lists (distance_kernels.h): hybrid and batched hybrid equal brute force
// within the tolerance on every pair of every set, at every scale; results do not depend on
// how a list is split.
#include "distance/distance_kernels.h"
#include "test_triangle_cases.h"

#include <gtest/gtest.h>

#include <limits>

using namespace tri;
using namespace tri_test;

namespace {

struct PairSet {
  TriangleSoA a, b;
  std::vector<TrianglePairIndex> pairs;
  std::vector<std::string> names;
};

PairSet make_set(double scale, std::uint64_t seed) {
  std::vector<TriangleCase> cases = adversarial_cases(scale, seed);
  for (const auto &c : random_cases(3000, scale, seed)) // random pairs within a few triangle sizes
    cases.push_back(c);
  PairSet s;
  cases_to_soa(cases, s.a, s.b, s.pairs);
  for (const auto &c : cases)
    s.names.push_back(c.name);
  return s;
}

// The job tests' settings (millimetre triangles): a cutoff the random pairs spread across, and
// the retry, as in the simulations.
HybridSettings job_settings() {
  HybridSettings hs;
  hs.tolerance = 1e-10;
  hs.cutoff = 0.0437e-3;
  hs.retry_iterations = 8;
  return hs;
}

} // namespace

class HybridAtScale : public ::testing::TestWithParam<double> {};

TEST_P(HybridAtScale, EqualsBruteForceWithinToleranceOnEveryPair) {
  const double scale = GetParam();
  const PairSet s = make_set(scale, 41);
  const int n = static_cast<int>(s.pairs.size());
  std::vector<TrianglePairDistance> bf(n), hy(n), bh(n);
  brute_force_distances(s.a, s.b, s.pairs.data(), n, bf.data());
  HybridSettings hs;
  hs.tolerance = 1e-7 * scale; // 1e-3 of a soft layer of 1e-4 of the triangle size
  HybridCounters counters;
  hybrid_distances(s.a, s.b, s.pairs.data(), n, hs, 0, hy.data(), counters);
  hybrid_distances(s.a, s.b, s.pairs.data(), n, hs, 8, bh.data(), counters);
  for (int k = 0; k < n; ++k) {
    ASSERT_NEAR(hy[k].distance, bf[k].distance, hs.tolerance) << s.names[k];
    ASSERT_NEAR(bh[k].distance, bf[k].distance, hs.tolerance) << s.names[k];
    ASSERT_EQ(hy[k].intersecting, bf[k].intersecting) << s.names[k];
    ASSERT_EQ(bh[k].intersecting, bf[k].intersecting) << s.names[k];
    ASSERT_NEAR(hy[k].normal.norm(), 1.0, 1e-12) << s.names[k];
  }
  EXPECT_EQ(counters.penalty_pairs, 2 * n);
  EXPECT_GT(counters.fallbacks, 0); // the sets contain intersecting pairs
}

INSTANTIATE_TEST_SUITE_P(Scales, HybridAtScale, ::testing::Values(1e-6, 1e-3, 1.0, 1e3));

TEST(Hybrid, ContactClassificationAgreesWithBruteForceAtTheCutoff) {
  // Cutoffs at 0.99 and 1.01 of each pair's own distance: the side must match exactly.
  const PairSet s = make_set(1e-3, 42);
  const int n = static_cast<int>(s.pairs.size());
  std::vector<TrianglePairDistance> bf(n), hy(n);
  brute_force_distances(s.a, s.b, s.pairs.data(), n, bf.data());
  for (double factor : {0.99, 1.01}) {
    for (int k = 0; k < n; ++k) {
      if (bf[k].distance == 0.0)
        continue;
      HybridSettings hs;
      hs.tolerance = 1e-10;
      hs.cutoff = factor * bf[k].distance;
      HybridCounters counters;
      hybrid_distances(s.a, s.b, &s.pairs[k], 1, hs, 0, &hy[k], counters);
      ASSERT_EQ(hy[k].distance < hs.cutoff, bf[k].distance < hs.cutoff) << s.names[k];
    }
  }
}

TEST(Hybrid, ResultsDoNotDependOnHowTheListIsSplit) {
  const PairSet s = make_set(1e-3, 43);
  const int n = static_cast<int>(s.pairs.size());
  HybridSettings hs;
  hs.tolerance = 1e-10;
  for (int batch : {0, 8}) {
    std::vector<TrianglePairDistance> whole(n), parts(n);
    HybridCounters c;
    hybrid_distances(s.a, s.b, s.pairs.data(), n, hs, batch, whole.data(), c);
    const int cut = batch ? 8 * 37 : 37; // split points at batch boundaries for batched
    hybrid_distances(s.a, s.b, s.pairs.data(), cut, hs, batch, parts.data(), c);
    hybrid_distances(s.a, s.b, s.pairs.data() + cut, n - cut, hs, batch, parts.data() + cut, c);
    for (int k = 0; k < n; ++k) {
      ASSERT_EQ(whole[k].distance, parts[k].distance) << s.names[k];
      ASSERT_EQ(whole[k].point_a, parts[k].point_a) << s.names[k];
      ASSERT_EQ(whole[k].normal, parts[k].normal) << s.names[k];
    }
  }
}

// The retry (HybridSettings::retry_iterations, on in the simulations): pairs the first 4 steps
// cannot certify go on to 8 before any fallback. Every pair stays within the tolerance of
// brute force, contacts at a cutoff agree with it exactly, fewer pairs fall back, and
// splitting the list (other pairs sharing the retry's lanes) changes no bits; at every scale.
TEST_P(HybridAtScale, RetryKeepsBruteForcesAnswersWithFewerFallbacks) {
  const double scale = GetParam();
  const PairSet s = make_set(scale, 45);
  const int n = static_cast<int>(s.pairs.size());
  std::vector<TrianglePairDistance> bf(n), plain(n), retried(n), parts(n);
  brute_force_distances(s.a, s.b, s.pairs.data(), n, bf.data());
  HybridSettings hs;
  hs.tolerance = 1e-7 * scale;
  hs.cutoff = 0.0437 * scale; // the random pairs spread across it (no case sits on it)
  HybridCounters without, with, split;
  hybrid_distances(s.a, s.b, s.pairs.data(), n, hs, 0, plain.data(), without);
  hs.retry_iterations = 8;
  hybrid_distances(s.a, s.b, s.pairs.data(), n, hs, 0, retried.data(), with);
  const int cut = 101;
  hybrid_distances(s.a, s.b, s.pairs.data(), cut, hs, 0, parts.data(), split);
  hybrid_distances(s.a, s.b, s.pairs.data() + cut, n - cut, hs, 0, parts.data() + cut, split);
  int contacts = 0;
  for (int k = 0; k < n; ++k) {
    ASSERT_EQ(retried[k].distance < hs.cutoff, bf[k].distance < hs.cutoff) << s.names[k];
    contacts += bf[k].distance < hs.cutoff;
    if (bf[k].distance < hs.cutoff) {
      ASSERT_NEAR(retried[k].distance, bf[k].distance, hs.tolerance) << s.names[k];
    }
    ASSERT_EQ(retried[k].intersecting, bf[k].intersecting) << s.names[k];
    ASSERT_EQ(parts[k].distance, retried[k].distance) << s.names[k];
    ASSERT_EQ(parts[k].point_a, retried[k].point_a) << s.names[k];
    ASSERT_EQ(parts[k].normal, retried[k].normal) << s.names[k];
  }
  EXPECT_GT(contacts, n / 20);
  EXPECT_EQ(with.retries, without.fallbacks); // every pair the first run left is retried
  EXPECT_GT(with.fallbacks, 0);               // intersecting pairs still need brute force
  EXPECT_LT(with.fallbacks, without.fallbacks);
  EXPECT_EQ(with.penalty_pairs, without.penalty_pairs); // retries are not in the histogram
}

// Many body pairs' lists at once (hybrid_distances_jobs, what the interaction engine runs):
// short lists of 1 to 11 pairs, with settings that differ from job to job (tolerance, cutoff,
// iteration counts, no retry, the penalty's step bound), so that blocks of the first run, of the retry and of brute
// force mix jobs and flush where the settings change. Every job's results are bitwise
// hybrid_distances' on its list alone, and the counters sum to theirs.
TEST(Hybrid, JobsRunTogetherGiveEachJobsOwnResults) {
  const PairSet s = make_set(1e-3, 47);
  const int n = static_cast<int>(s.pairs.size());
  const HybridSettings base = job_settings();
  std::vector<HybridJob> jobs;
  std::vector<TrianglePairDistance> together(n), alone(n);
  HybridCounters sum_alone;
  for (int first = 0, j = 0; first < n; ++j) {
    const int count = std::min(n - first, 1 + (j * 7) % 11);
    HybridSettings hs = base;
    if (j % 5 == 1)
      hs.tolerance = 3e-10;
    if (j % 7 == 2)
      hs.cutoff = 0.02e-3;
    if (j % 11 == 3)
      hs.retry_iterations = 0;
    if (j % 13 == 4)
      hs.newton_iterations = 8, hs.retry_iterations = 16;
    if (j % 3 == 2)
      hs.penalty.max_step = 0.25;
    jobs.push_back({&s.a, &s.b, s.pairs.data() + first, count, hs, together.data() + first});
    hybrid_distances(s.a, s.b, s.pairs.data() + first, count, hs, 0, alone.data() + first,
                     sum_alone);
    first += count;
  }
  HybridCounters sum_together;
  hybrid_distances_jobs(jobs.data(), static_cast<int>(jobs.size()), sum_together);
  for (int k = 0; k < n; ++k) {
    ASSERT_EQ(together[k].distance, alone[k].distance) << s.names[k];
    ASSERT_EQ(together[k].lower_bound, alone[k].lower_bound) << s.names[k];
    ASSERT_EQ(together[k].point_a, alone[k].point_a) << s.names[k];
    ASSERT_EQ(together[k].point_b, alone[k].point_b) << s.names[k];
    ASSERT_EQ(together[k].normal, alone[k].normal) << s.names[k];
    ASSERT_EQ(together[k].intersecting, alone[k].intersecting) << s.names[k];
  }
  EXPECT_GT(sum_together.retries, 0);
  EXPECT_GT(sum_together.fallbacks, 0);
  EXPECT_EQ(sum_together.penalty_pairs, sum_alone.penalty_pairs);
  EXPECT_EQ(sum_together.retries, sum_alone.retries);
  EXPECT_EQ(sum_together.fallbacks, sum_alone.fallbacks);
  for (int k = 0; k <= kMaxPenaltyIterations; ++k)
    EXPECT_EQ(sum_together.newton_histogram[k], sum_alone.newton_histogram[k]);
}

// Jobs with lower bounds (kept candidates, candidate_cache.h): a pair whose bound is at least
// skip_from is not run (its result: distance +inf, triangle_pairs_tested one less, no penalty
// or fallback counted); every other pair's result is bitwise that of the job without bounds,
// wherever the skipped pairs sat among its lanes. No bound, or skip_from infinite: nothing is
// skipped.
TEST(Hybrid, JobsSkipThePairsTheirLowerBoundsRuleOut) {
  const PairSet s = make_set(1e-3, 48);
  const int n = static_cast<int>(s.pairs.size());
  const HybridSettings hs = job_settings();
  std::vector<TrianglePairDistance> plain(n), skipping(n), unbounded(n);
  HybridCounters c_plain, c_skip, c_unbounded;
  const HybridJob job{&s.a, &s.b, s.pairs.data(), n, hs, plain.data()};
  hybrid_distances_jobs(&job, 1, c_plain);
  // Bounds: every third pair well beyond skip_from, the others below it (one exactly at it is
  // skipped: the bound rules it out).
  const double skip_from = 0.05e-3;
  std::vector<double> lower(n);
  int expect_skipped = 0;
  for (int k = 0; k < n; ++k) {
    lower[k] = k % 3 == 0 ? 2 * skip_from : (k % 3 == 1 ? 0.0 : 0.5 * skip_from);
    if (k == 7)
      lower[k] = skip_from;
    expect_skipped += lower[k] >= skip_from;
  }
  HybridJob with = job;
  with.out = skipping.data();
  with.lower = lower.data();
  with.skip_from = skip_from;
  hybrid_distances_jobs(&with, 1, c_skip);
  for (int k = 0; k < n; ++k) {
    if (lower[k] >= skip_from) {
      ASSERT_EQ(skipping[k].distance, std::numeric_limits<double>::infinity()) << s.names[k];
      continue;
    }
    ASSERT_EQ(skipping[k].distance, plain[k].distance) << s.names[k];
    ASSERT_EQ(skipping[k].lower_bound, plain[k].lower_bound) << s.names[k];
    ASSERT_EQ(skipping[k].point_a, plain[k].point_a) << s.names[k];
    ASSERT_EQ(skipping[k].point_b, plain[k].point_b) << s.names[k];
    ASSERT_EQ(skipping[k].intersecting, plain[k].intersecting) << s.names[k];
  }
  EXPECT_EQ(c_plain.triangle_pairs_tested, 0); // counted where a job is queued, not here
  EXPECT_EQ(c_skip.triangle_pairs_tested, -expect_skipped);
  EXPECT_EQ(c_skip.penalty_pairs, n - expect_skipped);
  EXPECT_LT(c_skip.fallbacks + c_skip.retries, c_plain.fallbacks + c_plain.retries);
  HybridJob infinite = with;
  infinite.out = unbounded.data();
  infinite.skip_from = std::numeric_limits<double>::infinity();
  hybrid_distances_jobs(&infinite, 1, c_unbounded);
  for (int k = 0; k < n; ++k)
    ASSERT_EQ(unbounded[k].distance, plain[k].distance) << s.names[k];
  EXPECT_EQ(c_unbounded.triangle_pairs_tested, 0);
  EXPECT_EQ(c_unbounded.penalty_pairs, c_plain.penalty_pairs);
}

TEST(Penalty, AloneIsCloseButUnchecked) {
  const PairSet s = make_set(1.0, 44);
  const int n = static_cast<int>(s.pairs.size());
  std::vector<TrianglePairDistance> bf(n), pe(n);
  brute_force_distances(s.a, s.b, s.pairs.data(), n, bf.data());
  HybridSettings hs;
  hs.newton_iterations = 32;
  HybridCounters c;
  penalty_distances(s.a, s.b, s.pairs.data(), n, hs, pe.data(), c);
  int close = 0;
  for (int k = 0; k < n; ++k) {
    EXPECT_GE(pe[k].distance, bf[k].distance - 1e-12); // an upper bound, always
    EXPECT_TRUE(pe[k].normal.allFinite());
    close += std::abs(pe[k].distance - bf[k].distance) < 1e-6;
  }
  EXPECT_GT(close, 0.9 * n);
}
