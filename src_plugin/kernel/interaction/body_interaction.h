// One interaction between two bodies made of triangles (two particles, or a particle and a
// patch of wall triangles): triangle-pair contacts (particle_contacts.h), their reduction to
// contact points (contact_reduction.h) and the contact force law (contact_force.h), in the
// order the paper's section 2 describes. The LIGGGHTS styles reach it only through the
// interaction engine (interaction_engine.h), so the pair style and the wall fix cannot drift
// apart.
//
// A body pair goes one way:
// 1. proven_apart: the pair's kept state (travel, gap, axis) proves the bodies apart, and the
//    pair takes apart_result. This is the only place that says a pair is apart without a
//    search; hosts ask it before they build world-frame triangles.
// 2. plan_body_pair, for a pair not proven apart: the search (or the kept candidates), and
//    either a finished result (the wall planes prove the bodies apart, the search finds no
//    candidates, or the kernel cannot be queued and runs at once) or a KernelRequest: the
//    hybrid distance job over the pair's candidates.
// 3. finish_body_pair, for a request: from the kernel's results on the job, the kept state,
//    the reduction and the force.
// Whoever runs a request's job, alone or beside other pairs' (hybrid_distances_jobs fills the
// vector lanes across body pairs), finish_body_pair returns the same bits: each triangle pair's
// result does not depend on the other pairs run with it.
#pragma once

#include "body/smooth_surface.h"
#include "contact/contact_reduction.h"
#include "contact/penetration_depth.h"
#include "distance/candidate_cache.h"
#include "distance/particle_contacts.h"
#include "interaction/kept_contacts.h"
#include "model/contact_force.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <variant>
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
  // Kept contact points (kept_contacts.h) are carried while the bodies move less than this
  // times eps_a + eps_b relative to each other; 0: every contact is measured every step.
  double kept_tolerance = kKeptContactTolerance;
};

// Per-thread scratch, owned by the caller, so the force loop allocates nothing once warmed up.
// Aligned to cache lines: the engine keeps one per thread side by side, and every task grows
// and shrinks its vectors (their pointers are in the struct).
struct alignas(64) InteractionScratch {
  ContactWorkspace distance;
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
  // Where the surface is a ball (smooth_surface.h: corner_spheres, 3 per triangle in
  // `triangles`' order, body frame); null elsewhere. Two balls meet as their spheres
  // (contact/ball_contact.h), and their search reaches epsilon + ball_lift.
  const SurfaceSphere *spheres = nullptr;
  double ball_lift = 0.0; // m, Shape::ball_lift
  bool convex = true;     // Shape::convex (a wall: unused)
  // A wall patch whose points may be kept (kept_contacts.h: a static mesh): each triangle's id
  // in its mesh, in `triangles`' order; null otherwise (a particle, a moving wall).
  const int *triangle_ids = nullptr;
  BodyState state;                        // mass <= 0 for a wall
  RigidPose pose; // a particle: x, orientation and bounding radius of `triangles`; unused for a wall
  // A particle: its body-frame triangles (those `pose` places; pose.frame points at them), so
  // that a kept separating axis is verified without `triangles` (separating_axis.h:
  // posed_extent). Null: `triangles` are read (a wall patch, a body a test built by hand).
  const TriangleSoA *frame = nullptr;

  bool is_wall() const { return !(state.mass > 0.0); }
  bool is_ball() const { return spheres != nullptr; }
  bool is_smooth() const { return edge_bulge != nullptr; }
  // The triangle search's reach against `other`, m: the ball's lift against another ball, the
  // smooth surface's lift against facets (a wall's, a cube's), none between two smooth surfaces
  // that are not both balls (body_interaction.cpp, reduction_params).
  double reach_epsilon(const Body &other) const {
    if (is_ball() && other.is_ball())
      return epsilon + ball_lift;
    return is_smooth() && !other.is_smooth() ? epsilon + lift : epsilon;
  }
};

// Whether exactly one of the two is a smooth surface (Body::edge_bulge) and the other its facets:
// that one is measured on its smooth surface (reduction_params). A wall is its facets.
inline bool smooth_on_facets(const Body &a, const Body &b) {
  return a.is_smooth() != b.is_smooth() && !(a.is_ball() && b.is_ball());
}

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
  // Two particles' running motion sums (candidate_cache.h: Travel), where the host keeps them:
  // proven_apart tries the travel proof first, and every gap proven is kept for it.
  Travel travel = {};
  // Two particles' kept contact points (kKeptContactDoubles values, kept_contacts.h, in the
  // orientation (a, b)), where the host keeps them; null: none kept.
  double *kept_contacts = nullptr;
};

// Whether the kept state of the pair proves a and b apart: the travel proof, then the kept gap
// (candidate_cache.h), then the kept axis. For bodies with a `frame` (particles) it reads their
// poses only, never `triangles` (which may be stale); a wall patch's triangles are read. With
// cache.update, a gap proven is kept (for the travel proof too). A pair proven apart takes
// apart_result; any other goes to plan_body_pair (asking again changes nothing).
bool proven_apart(const Body &a, const Body &b, const InteractionSettings &s,
                  SeparationCache cache);
// proven_apart's first proof alone, which reads neither body: the travel proof (candidate_cache.h,
// Travel) of two particles with kept candidates `kept` (null: none kept), `cutoff` their
// particle_pair_cutoff. For a host that passes over such pairs before it builds their bodies:
// they change nothing, and count as apart_result(stats) would (InteractionTally::add_passed).
bool proven_apart_by_travel(const CandidateCache *kept, const Travel &travel, double cutoff);
// The distance below which the triangles of two particles with soft layers eps_a and eps_b and
// lifts lift_a and lift_b may touch (Body::reach_epsilon: 0 where the lift does not count).
inline double particle_pair_cutoff(double eps_a, double eps_b, double lift_a = 0.0,
                                   double lift_b = 0.0) {
  return eps_a + eps_b + lift_a + lift_b;
}
// The result of a pair without contacts (proven apart, or a search that finds none): no force,
// the history cleared. `history` as for plan_body_pair.
PairForceResult apart_result(const Body &a, const Body &b, const InteractionSettings &s, double dt,
                             double *history, InteractionScratch &scratch, ContactStats &stats);
// apart_result for a pair whose history (as stored by the host, either orientation) is clear
// or not kept: nothing to clear, so neither the history nor the coefficients are needed. Most
// neighbour pairs of a pile are apart with a clear history; the host skips their view.
bool apart_needs_nothing(const double *stored_history);
PairForceResult apart_result(ContactStats &stats);

// Whether the pair's kept contact points (SeparationCache::kept_contacts) are carried this step
// rather than measured: two particles, or a particle and a static wall patch (one with
// triangle_ids, whose kept triangles it still holds), whose relative motion since the points
// were kept is within s.kept_tolerance of their layer (kept_contacts.h). Reads the bodies' poses only, never
// their triangles, so a host asks before it builds them; plan_body_pair then carries them.
bool kept_contacts_hold(const Body &a, const Body &b, const InteractionSettings &s,
                        const SeparationCache &cache);
// The result of a pair whose kept contact points hold (kept_contacts_hold): the force law on the
// points carried to the bodies' poses. plan_body_pair gives it too; a host that asked
// kept_contacts_hold already calls this instead, and the motion is not bounded twice.
PairForceResult carried_contacts_result(const Body &a, const Body &b, const InteractionSettings &s,
                                        double dt, double *history, InteractionScratch &scratch,
                                        ContactStats &stats, const SeparationCache &cache);

// Which candidates a kernel request runs on, and what finish_body_pair does with them.
enum class CandidateList {
  kept,             // the pair's kept candidates (candidate_cache.h): rebased on the results
  searched,         // a fresh search's (in scratch.distance.pairs until the next search)
  searched_to_keep, // the same, kept afterwards with KernelRequest::reach
};

// The distance-kernel work of a body pair (plan_body_pair): the unbatched hybrid's job on its
// candidates (particle_contacts.h: queue_candidates; the pairs tested and culled are counted
// already). job.out is the runner's to point at job.count results. job.pairs points at the kept
// candidates, or at the scratch's search list, which the next plan with that scratch
// overwrites: a runner that plans other pairs first copies them (KernelQueue).
struct KernelRequest {
  HybridJob job;
  CandidateList candidates = CandidateList::kept;
  double reach = 0.0; // m, searched_to_keep only (candidate_reach)
};

// What plan_body_pair gives: the pair's result, or the kernel job that finish_body_pair needs.
using PairPlan = std::variant<PairForceResult, KernelRequest>;

// The forces between a (a particle) and b (a particle or a wall) for one time step of length
// dt, up to the distance kernel, for a pair that proven_apart has not proven apart (it is not
// asked again). `history` holds kHistoryDoubles values kept by the host for this pair (null
// for tangential no_history). Statistics of the distance kernel are added to `stats`. The
// reference direction of the reduction (contact_reduction.h: for intersecting triangles
// without a usable normal) is the line of centres for two particles, and for a wall the
// direction from a's centre to the closest point of the patch. Contacts whose real surfaces
// intersect get their depth through the intersection (penetration_depth.h) before the force
// law; the result carries the combined layer and the resolvable depth so that the host can
// stop a contact deeper than that. `cache` as above (default: none); the result depends on it
// only through kept contact points: where they hold (kept_contacts_hold) they are carried, and
// the outcome is the result without a search (within kept_contacts.h's tolerance of a
// measurement); a pair measured with kept_contacts and cache.update keeps its points for the
// next step. Where the kernel can be queued (can_queue_candidates) and there are candidates,
// the outcome is a KernelRequest; else the kernel runs at once and the outcome is the result.
PairPlan plan_body_pair(const Body &a, const Body &b, const InteractionSettings &s, double dt,
                        double *history, InteractionScratch &scratch, ContactStats &stats,
                        SeparationCache cache = {});
// The rest of the interaction that plan_body_pair requested `request` for, from `results`
// (request.job.count of them, in its pairs' order): the same arguments as for the plan (the
// history and kept state untouched in between), and the same bits as where the kernel runs at
// once.
PairForceResult finish_body_pair(const Body &a, const Body &b, const InteractionSettings &s,
                                 double dt, double *history, InteractionScratch &scratch,
                                 ContactStats &stats, SeparationCache cache,
                                 const KernelRequest &request, const TrianglePairDistance *results);

// The reach (m) a search keeps its candidates with: coherence x cutoff, or, for bodies that
// move faster, what their relative motion covers in kCandidateSteps steps (translation plus
// each spin times its radius, a wall's radius 0), at most kCandidateReachCap cutoffs. A choice
// of cost only (candidate_cache.h proves each reuse from the actual motion): too small, and
// colliding bodies search afresh every step (a granular gas); too large, and a list holds
// pairs that never come close. A search costs as much as some 40 kernel pairs. 32 steps rather
// than 8 since lists are bounded by the pair's relative motion: in the paper's formed hopper
// 52 searches a step instead of 122 for 3 % more pairs tested, 14 % fewer instructions; the
// granular gas the same to 0.1 %; a settled pile's reach is the coherence's either way.
constexpr double kCandidateSteps = 32.0, kCandidateReachCap = 1.0;
double candidate_reach(const Body &a, const Body &b, double coherence, double cutoff, double dt);

} // namespace tri
