// Distances of a list of triangle pairs by each kernel: brute force (vectorised), penalty
// alone, hybrid (penalty, then brute force for every pair the penalty cannot certify) and
// batched hybrid (the paper's Algorithm 1: a whole batch falls back when one of its pairs
// does). These are the loops the particle-pair driver (particle_contacts.h) runs on each
// thread's share of the candidate pairs; the tri-distance tool and the tests call them too.
//
// Pair k is triangle pairs[k].a of `a` against triangle pairs[k].b of `b`. Results are
// written to out[k] (TrianglePairDistance, triangle_distance.h), in the unit of the input.
// Pairs are processed in blocks of kPairLanes, padded, so a pair's result does not depend
// on its position in the list or on which other pairs share its block: splitting a list
// into sub-lists (threads) gives bit-identical results. (The batched hybrid's fallback
// decision does depend on the batch, so callers split it at batch boundaries only.)
#pragma once

#include <limits>

#include "distance/penalty_distance.h"
#include "distance/triangle_distance.h"
#include "geometry/triangle_soa.h"

namespace tri {

struct TrianglePairIndex {
  int a, b; // triangle indices in the two TriangleSoA
};

struct HybridSettings {
  int newton_iterations = 4; // one of penalty_iterations_supported()
  PenaltyParameters penalty; // scale-free weights, penalty_distance.h
  // Absolute error (length) accepted from the penalty: a pair is kept from the penalty only
  // if it is proven separated (lower > 0) and upper - lower <= tolerance; its distance is
  // then within `tolerance` of the true distance (penalty_distance.h). Everything else
  // is recomputed by brute force.
  double tolerance = 0.0;
  // Contact cutoff (length). Pairs proven at or beyond it (lower >= cutoff) need no exact
  // distance: they keep the penalty's upper bound (>= cutoff). Pairs whose bounds straddle
  // the cutoff always fall back, so "distance < cutoff" agrees with brute force exactly.
  // INFINITY asks for every distance within tolerance.
  double cutoff = INFINITY;
  // Hybrid without batches: a pair the first run cannot certify goes on from where that run
  // stopped to this many steps in all (penalty_block_resume; when the difference is one of
  // penalty_resume_supported()), before it falls back. In a settled pile a fifth of the
  // pairs needs more than 4 steps (an active-set change per step from the centroids) and
  // three quarters of those are certified by 8, at a fifth of a brute-force evaluation. The
  // verdict is the same rigorous test, so results stay within `tolerance` and contacts agree
  // with brute force; 0: no second run.
  int retry_iterations = 0;
};

// Newton histogram and fallbacks; values summed by the caller. ContactStats
// (particle_contacts.h) extends this with the culling counters.
struct HybridCounters {
  long long triangle_pairs_tested = 0; // pairs given to the distance kernel
  long long penalty_pairs = 0; // pairs run through the penalty
  long long fallbacks = 0;     // pairs recomputed by brute force
  long long retries = 0;       // pairs run a second time (retry_iterations), not in the histogram
  // newton_histogram[k], k >= 1: pairs whose k-th Newton step was the first shorter than
  // the tolerance (in length: s |dz|); [0]: no step was within the iteration count.
  long long newton_histogram[kMaxPenaltyIterations + 1] = {};

  HybridCounters &operator+=(const HybridCounters &o);
};

// Brute force on every pair (vectorised 15 checks, brute_force_block).
void brute_force_distances(const TriangleSoA &a, const TriangleSoA &b,
                           const TrianglePairIndex *pairs, int count, TrianglePairDistance *out);

// Scalar brute force (triangle_distance) on every pair: the reference.
void brute_force_scalar_distances(const TriangleSoA &a, const TriangleSoA &b,
                                  const TrianglePairIndex *pairs, int count,
                                  TrianglePairDistance *out);

// Penalty alone, no check: distance = upper bound of penalty_distance.h, which may exceed
// the true distance by any amount when the iteration has not converged; intersecting when
// upper <= the brute force's touch tolerance (normal then from min_overlap_axis). For
// studies and benchmarks, not for simulations.
void penalty_distances(const TriangleSoA &a, const TriangleSoA &b, const TrianglePairIndex *pairs,
                       int count, const HybridSettings &settings, TrianglePairDistance *out,
                       HybridCounters &counters);

// Hybrid. batch_size <= 0: every pair decides alone (after the second run of
// HybridSettings::retry_iterations, if set). batch_size > 0: pairs
// [k*batch_size, (k+1)*batch_size) form batch k, and if any pair of a batch is neither
// accepted nor beyond the cutoff the whole batch is recomputed by brute force. Accepted
// pairs: distance = upper, points p, q, normal (q - p) / upper, not intersecting; fallback
// pairs: exactly brute_force_distances' result.
void hybrid_distances(const TriangleSoA &a, const TriangleSoA &b, const TrianglePairIndex *pairs,
                      int count, const HybridSettings &settings, int batch_size,
                      TrianglePairDistance *out, HybridCounters &counters);

// The unbatched hybrid (batch_size <= 0) on the pair lists of many body pairs at once. Each
// job's first penalty run goes block by block over its own list, as hybrid_distances does;
// the pairs that run cannot certify are retried, and those the retry cannot certify are
// brute-forced, in blocks filled across jobs. A settled pile's body pair has about 7
// candidates of which 1 or 2 need a retry: per body pair, the retry and the brute force ran
// on blocks with most of their lanes idle. Every lane's result depends on its own pair only
// (penalty_distance.h, brute_force_block), so each job's results are bitwise those of
// hybrid_distances on its list alone, however the jobs are grouped.
struct HybridJob {
  const TriangleSoA *a, *b;        // must outlive the call
  const TrianglePairIndex *pairs;  // [0, count)
  int count;
  HybridSettings settings;
  TrianglePairDistance *out;       // [0, count)
  // Optional, [0, count): a lower bound on each pair's distance (kept candidates,
  // candidate_cache.h). A pair whose bound is at least `skip_from` (finite) is not run: its
  // result is only distance = +infinity, and it is taken back from triangle_pairs_tested.
  const double *lower = nullptr;
  double skip_from = std::numeric_limits<double>::infinity();
};
void hybrid_distances_jobs(const HybridJob *jobs, int num_jobs, HybridCounters &counters);

} // namespace tri
