// One interaction between two bodies made of triangles (two particles, or a particle and a
// patch of wall triangles): triangle-pair contacts (particle_contacts.h), their reduction to
// contact points (contact_reduction.h) and the contact force law (contact_force.h), in the
// order the paper's section 2 describes. The LIGGGHTS styles call only this, so the pair
// style and the wall fix cannot drift apart.
#pragma once

#include "contact/contact_reduction.h"
#include "contact/penetration_depth.h"
#include "distance/candidate_cache.h"
#include "distance/particle_contacts.h"
#include "model/contact_force.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace tri {

struct InteractionSettings {
  ContactOptions distance;                     // kernel, culling, threads inside the pair
  ReductionMethod reduction = ReductionMethod::clusters;
  ContactCoefficients coefficients;            // per type pair, filled by the host
  // Kept candidates (candidate_cache.h): searched with a margin of the cutoff plus a reach of
  // coherence x the cutoff (more for fast bodies: candidate_reach) and reused while the bodies
  // move less than the reach; 0: none kept.
  // Not with the batched kernel, whose result for a pair depends on its batch.
  double coherence = 0.05;
};

// Per-thread scratch, owned by the caller, so the force loop allocates nothing once warmed up.
// Aligned to cache lines: the engine keeps one per thread side by side, and every task grows
// and shrinks its vectors (their pointers are in the struct).
struct alignas(64) InteractionScratch {
  ContactWorkspace distance;
  // What contacts_among_candidates appends where a pair's kernel runs at once (not queued);
  // the reduction reads the kernel's results in place (reduce_kernel_results).
  std::vector<TriangleContact> triangle_contacts;
  std::vector<ContactPoint> points;
  // Where a host that asked (record_contacts) gets one ContactRecord per contact point of every
  // body pair evaluated with this scratch, appended in evaluation order (the engine keeps each
  // task's range: InteractionEngine::records); the reduction then also classifies the points.
  bool record_contacts = false;
  std::vector<ContactRecord> records;
  ReductionWorkspace reduction;
  DepthScratch depth;
  // Wall triangles proven apart from the particle by their own planes, and those planes.
  std::vector<std::uint8_t> wall_apart;
  TrianglePlanes wall_planes;
  // Kernel work deferred by the engine (interaction_engine.h). While `defer` is set, a body
  // pair that reaches the distance kernel (its kept candidates, or a search's) queues its
  // hybrid job (queue_candidates) and returns at once with an empty result; the engine runs
  // the queued jobs together (their first runs, retries and fallbacks fill the vector lanes
  // across body pairs) and calls again with `resume_job` set to the pair's job, which goes on
  // from the results exactly where the direct call would.
  bool defer = false;
  int resume_job = -1;
  std::vector<HybridJob> jobs;
  // Per job: where a search's candidates were copied (job_pairs; -1 for a kept list, which
  // stays where it is), and whether the search keeps them, with what reach.
  struct JobOrigin {
    std::ptrdiff_t pairs_offset = -1;
    bool keep = false;
    double reach = 0.0;
  };
  std::vector<JobOrigin> job_origins;
  std::vector<TrianglePairIndex> job_pairs;
  std::vector<std::size_t> job_offsets; // job j's results: job_results[job_offsets[j]...]
  std::vector<TrianglePairDistance> job_results;
  // Runs the queued jobs (counters into `stats`); the results stay until the next clear_jobs.
  void run_jobs(HybridCounters &stats);
  void clear_jobs() {
    jobs.clear();
    job_origins.clear();
    job_pairs.clear();
    job_offsets.clear();
  }

  std::size_t bytes() const; // heap memory held (approximate for the reduction's vectors)
};

// A particle, or a wall patch: a body of infinite mass (state.mass <= 0) whose state is the
// rigid motion of its triangles (rigid_motion.h): x the centre of that motion, v its velocity
// there, omega its spin, so that the wall's velocity at any contact point is exact.
struct Body {
  const TriangleSoA *triangles = nullptr; // world frame
  double epsilon = 0.0;                   // soft-layer width, m
  double longest_edge = 0.0;              // m; infinity for a wall patch
  double min_edge = 0.0;                  // m, the paper's minimum mesh width
  // m, the shape's thinnest extent (penetration_depth.h: sets how deep a contact may be);
  // infinity for a wall patch
  double thinnest = std::numeric_limits<double>::infinity();
  // The smooth surface the shape's mesh samples (smooth_surface.h: 3 lifts per triangle, in
  // `triangles`' order); null where the facets are the body (a wall patch, a rock, a cube).
  const double *edge_bulge = nullptr;
  // m, how far that surface rises above the facets at most (Shape::surface_lift): the triangle
  // search reaches epsilon + lift, the layer stays epsilon (contact_reduction.h, step 5b).
  double lift = 0.0;
  BodyState state;                        // mass <= 0 for a wall
  RigidPose pose; // a particle: x, orientation and bounding radius of `triangles`; unused for a wall
  // A particle: its body-frame triangles (those `pose` places; pose.frame points at them), so
  // that a kept separating axis is verified without `triangles` (separating_axis.h:
  // posed_extent). Null: `triangles` are read (a wall patch, a body a test built by hand).
  const TriangleSoA *frame = nullptr;

  bool is_wall() const { return !(state.mass > 0.0); }
  // The triangle search's reach against `other`, m: the lift counts against walls only
  // (body_interaction.cpp after_kernel: particle pairs keep their facets).
  double reach_epsilon(const Body &other) const {
    return other.is_wall() ? epsilon + lift : epsilon;
  }
};

// The separating axis the host keeps for one body pair between steps (separating_axis.h):
// `axis` holds 3 doubles, world frame, pointing from a towards b, all zero for none. A stored
// axis is verified first; if it still proves the bodies apart (O(vertices)), no triangle pair
// is examined and the result is exactly the full search's (no contacts). Otherwise, for a wall
// patch, each wall triangle's own plane is tested (the particle entirely beyond it: that
// triangle is not searched; all of them: apart, also for a patch that wraps round the particle,
// where no single axis exists); then the full search runs and, when it finds no contact and
// `update` is set, a new axis is stored if it proves the bodies apart (the direction between
// the closest points tested, between the centres, or along the nearest face normals), else
// zero. A contact clears it. Values flip sign with the roles of a and b.
// `candidates`: the pair's kept triangle-pair candidates (candidate_cache.h), null for none;
// used when they still cover the bodies, else searched afresh (and kept, with `update`).
struct SeparationCache {
  double *axis = nullptr; // null: no cache kept
  bool update = true;     // false: read only (LIGGGHTS's setup of a run)
  CandidateCache *candidates = nullptr;
  // The host has called proven_apart for this step and it returned false: not repeated.
  bool not_apart = false;
  // Two particles' running motion sums (candidate_cache.h: Travel), where the host keeps them:
  // proven_apart tries the travel proof first, and every gap proven is kept for it.
  Travel travel = {};
};

// Forces between a (a particle) and b (a particle or a wall) for one time step of length dt.
// `history` holds kHistoryDoubles values kept by the host for this pair (null for tangential
// no_history). Statistics of the distance kernel are added to `stats`. The reference direction
// of the reduction (contact_reduction.h: for intersecting triangles without a usable normal)
// is the line of centres for two particles, and for a wall the direction from a's centre to
// the closest point of the patch. Contacts whose real surfaces intersect get their depth through
// the intersection (penetration_depth.h) before the force law; the result carries the combined
// layer and the resolvable depth so that the host can stop a contact deeper than that.
// `cache` as above (default: none; the result does not depend on it).
PairForceResult body_interaction(const Body &a, const Body &b, const InteractionSettings &s,
                                 double dt, double *history, InteractionScratch &scratch,
                                 ContactStats &stats, SeparationCache cache = {});

// body_interaction's first step, for a host that builds world-frame triangles only for the
// pairs that need them: true when the kept gap (candidate_cache.h) or the kept axis proves a
// and b apart. For bodies with a `frame` (particles) it reads their poses only, never
// `triangles` (which may be stale); a wall patch's triangles are read. Keeps the gap as
// body_interaction does (with cache.update). A pair proven apart takes apart_result(), exactly
// body_interaction's result for it; any other pair goes through body_interaction with
// cache.not_apart set (without it, the test is made again: it changes nothing when it fails).
bool proven_apart(const Body &a, const Body &b, const InteractionSettings &s,
                  SeparationCache cache);
PairForceResult apart_result(const Body &a, const Body &b, const InteractionSettings &s,
                             double dt, double *history, InteractionScratch &scratch,
                             ContactStats &stats);
// apart_result for a pair whose history (as stored by the host, either orientation) is clear
// or not kept: nothing to clear, so neither the history nor the coefficients are needed. Most
// neighbour pairs of a pile are apart with a clear history; the host skips their view.
bool apart_needs_nothing(const double *stored_history);
PairForceResult apart_result(ContactStats &stats);

// The reach (m) a search keeps its candidates with: coherence x cutoff, or, for bodies that
// move faster, what their relative motion covers in kCandidateSteps steps (translation plus
// each spin times its radius, a wall's radius 0), at most kCandidateReachCap cutoffs. A choice
// of cost only (candidate_cache.h proves each reuse from the actual motion): too small, and
// colliding bodies search afresh every step (a granular gas); too large, and a list holds
// pairs that never come close. 8 steps rather than 4: in the paper's hopper and a settled pile
// 1 to 3 % less time (a search costs as much as some 40 kernel pairs), in the granular gas
// 13 % more pairs tested and about 5 % more time.
constexpr double kCandidateSteps = 8.0, kCandidateReachCap = 1.0;
double candidate_reach(const Body &a, const Body &b, double coherence, double cutoff, double dt);

} // namespace tri
