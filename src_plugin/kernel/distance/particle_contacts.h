// Triangle contacts between two particles (or a particle and a wall patch): the step of a
// DEM time step that finds every triangle pair closer than the sum of the soft-layer
// widths (paper, sections 2-4; DESIGN.md, "One time step", item 4).
//
// Steps: optional cull of triangle pairs whose bounding boxes, grown by eps_a + eps_b, do
// not overlap (triangle_boxes.h: never drops a pair in contact); a distance kernel on the
// remaining pairs (distance_kernels.h); every pair with distance < eps_a + eps_b reported.
//
// Units: lengths in the unit of the triangles (metres in the simulation); eps_a, eps_b >= 0,
// their sum > 0 (a wall's layer is 0).
// Boundary: a pair at distance exactly eps_a + eps_b is not in contact.
// Accuracy: BruteForce / BruteForceScalar are the reference (triangle_distance.h).
// Hybrid and BatchedHybrid report the same set of pairs as brute force, and each reported
// distance within tolerance_ratio * min(eps_a, eps_b) of brute force's (the positive one
// where the other is 0, a wall's; pairs whose penalty bounds straddle the cutoff are
// recomputed by brute force). Penalty alone is unchecked (distance_kernels.h), for studies.
// Threads: results (values and order) are identical for every parallel mode and thread
// count; `parallel` opens an OpenMP parallel region inside the call, so callers that
// parallelise over particle pairs pass ContactParallelism::None. Only a list of at least
// kMinSharedPairs candidates is shared among threads (shares_among_threads): a particle pair
// of small rocks has about ten, a few microseconds of work, less than the region's start and
// join on two threads, and each thread's part would fill a fraction of a kernel block. Shorter
// lists run on the calling thread as ContactParallelism::None runs them, queued with other
// pairs' where the caller batches kernels (can_queue_candidates). The threshold is a fixed
// count, not a function of the thread count, so a pair takes the same path on any number of
// threads.
#pragma once

#include "distance/distance_kernels.h"
#include "distance/penalty_distance.h"
#include "distance/triangle_boxes.h"
#include "geometry/triangle_soa.h"

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <vector>

namespace tri {

enum class DistanceKernel {
  BruteForce,       // 15 checks + intersection test, vectorised across triangle pairs
  Penalty,          // penalty alone, unchecked
  Hybrid,           // penalty; each uncertified pair recomputed by brute force
  BatchedHybrid,    // penalty; a batch with one uncertified pair recomputed by brute force
  BruteForceScalar, // brute force one pair at a time (the reference; for benchmarks)
};

// Candidates from which on a list is shared among the threads of `parallel` (header): 16
// blocks of kPairLanes, 8 per thread on two, each a microsecond or so of penalty steps.
constexpr int kMinSharedPairs = 256;

enum class ContactParallelism {
  None,          // the calling thread does everything
  TrianglePairs, // OpenMP threads share the triangle pairs (the paper's triangle decomposition)
  Batches,       // OpenMP loop over batches of batch_size pairs (the paper's Algorithm 1)
};

constexpr long long kMaxUnculledPairs = 1LL << 22;

struct ContactOptions {
  DistanceKernel kernel = DistanceKernel::Hybrid;
  ContactParallelism parallel = ContactParallelism::None;
  int batch_size = 8; // pairs per batch: BatchedHybrid's fallback unit, Batches' work unit
  // false: every pair goes to the kernel (a diagnostic). Above kMaxUnculledPairs pairs the
  // cull runs anyway: it drops only pairs that cannot be in contact, so the contacts are the
  // same, and without it two 1e5-triangle shapes would need 1e10 pairs (terabytes).
  bool cull = true;
  // With cull: also boxes in a frame along the line between the two bodies' box centres and
  // the separating-axis test per pair (triangle_boxes.h: cull_triangle_pairs_two_frames,
  // separating_axis_filter);
  // false: world-frame boxes only (the plain cull, for comparison). Same contacts either way.
  bool tight_cull = true;
  int newton_iterations = 4;     // penalty steps; one of penalty_iterations_supported()
  // Hybrid: the second penalty run of the pairs the first cannot certify, before brute force
  // (distance_kernels.h: HybridSettings::retry_iterations); 0 or <= newton_iterations: none.
  int retry_iterations = 8;
  double tolerance_ratio = 1e-4; // hybrid distance tolerance / min(eps_a, eps_b) (above)
  PenaltyParameters penalty;     // scale-free penalty weight and regularisation
};

struct TriangleContact {            // one triangle pair closer than eps_a + eps_b
  int tri_a, tri_b;                 // triangle indices in a and b
  double distance;                  // >= 0; 0 when the triangles intersect
  Eigen::Vector3d point_a, point_b; // closest points on triangle a and b (equal when
                                    // intersecting: a point of both)
  Eigen::Vector3d normal;           // unit, from a towards b; when intersecting the
                                    // minimum-overlap axis (triangle_intersection.h)
  bool intersecting;
  double penetration_depth; // intersecting only: translation of b along normal that
                            // separates the triangles; 0 otherwise
  // The distance is exact (brute force, or a penalty result whose certified lower bound
  // reaches it), not only within the kernel's tolerance: the reduction need not recompute it.
  bool exact = false;
  // The triangles are certified not to intersect (a positive lower bound of their distance).
  bool apart = false;
};

// Values for one or more calls, summed by the caller; no globals. The penalty counters
// (penalty_pairs, fallbacks, newton_histogram) are the distance kernels' own (HybridCounters);
// what compute tri/stats reports of them is listed in interaction_tally.h.
struct ContactStats : HybridCounters { // triangle_pairs_tested among HybridCounters'
  long long triangle_pairs_culled = 0; // pairs removed by the box cull
  long long contacts = 0;              // pairs reported
  long long bodies_separated = 0;      // body pairs proven apart without a search (a kept
                                       // axis, wall planes: body_interaction.h)
  long long candidates_kept = 0;       // body pairs searched among kept candidates
                                       // (candidate_cache.h), not culled afresh
  long long contacts_carried = 0;      // body pairs whose kept contact points were carried
                                       // (interaction/kept_contacts.h), not measured

  ContactStats &operator+=(const ContactStats &o);
};

// Scratch of a body pair's search and kernel run (below), owned by the caller (one per thread),
// so that a call allocates nothing once the buffers have grown. Holds no state that outlives a
// call. `pairs` only grows (its first `count` entries are a call's), so it is not re-initialised.
struct ContactWorkspace {
  TriangleBoxes boxes_a, boxes_b;
  CullScratch cull;
  TriangleSoA frame_a, frame_b; // the triangles in the cull's second frame
  TriangleBoxes frame_boxes_a, frame_boxes_b;
  std::vector<TrianglePairIndex> pairs;
  std::vector<TrianglePairDistance> results;
  int tested = 0; // pairs of the last call: pairs[0, tested) with results[0, tested)

  std::size_t bytes() const; // heap memory held
};

// A body pair's contacts come from the distance kernel run on its candidate triangle pairs in
// one of two ways, which give the same bits where both apply (the unbatched hybrid: each pair's
// result depends neither on the other pairs in its list nor on the lists run beside it,
// distance_kernels.h):
// - at once: find_candidate_pairs, then distances_among_candidates (any kernel, any
//   parallelism);
// - queued: queue_candidates makes the unbatched hybrid's job, which the caller runs with other
//   body pairs' jobs (hybrid_distances_jobs, interaction_engine.h) where can_queue_candidates.
// Either way the pairs closer than eps_a + eps_b are the contacts (is_triangle_contact), sorted
// by (tri_a, tri_b) as the candidates are, so that results do not depend on the thread count.
// Both throw std::invalid_argument for an unsupported newton_iterations or batch_size < 1.

// Fills ws.pairs[0, count) (returned) with the triangle pairs the cull keeps for `margin`
// (every pair closer than margin is among them), in row-major (tri_a, tri_b) order.
// `skip_b` (optional, one entry per triangle of b): triangles of b the caller has proven
// farther than `margin` from all of a (body_interaction.cpp: wall triangles whose plane a
// lies beyond); with the tight cull they are not searched. The pairs are the same.
int find_candidate_pairs(const TriangleSoA &a, const TriangleSoA &b, double margin,
                         const ContactOptions &opt, ContactWorkspace &ws,
                         const std::uint8_t *skip_b = nullptr);
// Runs the distance kernel on pairs[0, count) (row-major order, any superset of the pairs
// closer than eps_a + eps_b) into ws.results[0, count) (ws.tested = count), and counts the
// pairs tested and culled and the kernel's own counters into `stats`; the contacts are not
// counted (the caller reads the results: count_triangle_contacts).
void distances_among_candidates(const TriangleSoA &a, double eps_a, const TriangleSoA &b,
                                double eps_b, const ContactOptions &opt,
                                const TrianglePairIndex *pairs, int count, ContactStats &stats,
                                ContactWorkspace &ws);

// Whether `count` candidates can be queued: the unbatched hybrid (a batch's fallback depends on
// its neighbours) on a list that is not shared among threads.
bool can_queue_candidates(const ContactOptions &opt, int count);
// Whether `count` candidates are shared among threads under opt.parallel (header, Threads).
bool shares_among_threads(const ContactOptions &opt, int count);
// The hybrid job of distances_among_candidates on pairs[0, count), for a caller that runs it
// with others; counts the pairs tested and culled into `stats` (the kernel's own counters are
// the run's). Its `out` is left for the caller to point at `count` results. `lower`,
// `skip_from` (optional): lower bounds on the pairs' distances (HybridJob's: kept candidates
// skip the pairs they rule out; their results are +infinity, never contacts).
HybridJob queue_candidates(const TriangleSoA &a, double eps_a, const TriangleSoA &b, double eps_b,
                           const ContactOptions &opt, const TrianglePairIndex *pairs, int count,
                           ContactStats &stats, const double *lower = nullptr,
                           double skip_from = std::numeric_limits<double>::infinity());
// How far above the exact distance a contact's distance from this kernel may lie (m): the
// hybrid's certified tolerance, 0 for brute force, infinity for the unchecked penalty.
double certified_tolerance(const ContactOptions &opt, double eps_a, double eps_b);

// Whether a kernel result is a triangle contact (closer than the cutoff), and how many of
// `count` results are: the one rule, for contacts_from_results and for callers that read the
// results in place (reduce_kernel_results).
inline bool is_triangle_contact(const TrianglePairDistance &r, double cutoff) {
  return r.distance < cutoff;
}
int count_triangle_contacts(const TrianglePairDistance *results, int count, double cutoff);
// What a kernel result certifies (TriangleContact::exact and ::apart).
inline bool certified_exact(const TrianglePairDistance &r) { return r.lower_bound >= r.distance; }
inline bool certified_apart(const TrianglePairDistance &r) {
  return !r.intersecting && r.lower_bound > 0.0;
}
// Appends to `out` the TriangleContact of each of results[0, count) that is a contact, and
// counts them into stats.contacts.
void contacts_from_results(const TrianglePairIndex *pairs, const TrianglePairDistance *results,
                           int count, double cutoff, std::vector<TriangleContact> &out,
                           ContactStats &stats);

} // namespace tri
