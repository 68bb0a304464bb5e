#include "interaction/body_interaction.h"

#include "contact/ball_contact.h"
#include "distance/separating_axis.h"
#include "geometry/point_triangle.h"
#include "model/contact_history.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tri {

namespace {

// The reduction's points lie midway between the two surfaces the kernel measures; each body's
// contact surface lies its layer beyond its own, so midway through the overlap of the contact
// surfaces is (eps_a - eps_b) / 2 further along the normal: no shift for two particles of one
// layer, half the particle's layer towards a wall that has none (the lever of rolling and
// friction is then the particle's own radius, and a resting body's wall contact sits on the
// wall's mesh).
void place_between_given_surfaces(double eps_a, double eps_b, std::vector<ContactPoint> &points) {
  const double shift = 0.5 * (eps_a - eps_b);
  if (shift == 0.0)
    return;
  for (ContactPoint &p : points) {
    p.point += shift * p.normal;
    p.damping_point += shift * p.normal;
  }
}

// Where no normal is defined (coincident triangles), push along the line of centres, or for a
// wall along the direction from the particle's centre to the wall's closest point.
// O(patch triangles), small beside the triangle pairs of the same interaction.
Eigen::Vector3d reference_direction(const Body &a, const Body &b) {
  Eigen::Vector3d towards = b.state.x - a.state.x;
  if (b.is_wall()) {
    double best = std::numeric_limits<double>::infinity();
    const TriangleSoA &t = *b.triangles;
    for (int k = 0; k < t.num_triangles(); ++k) {
      const Eigen::Vector3d q = closest_point_on_triangle(a.state.x, t.vertex(k, 0),
                                                          t.vertex(k, 1), t.vertex(k, 2));
      const double d2 = (q - a.state.x).squaredNorm();
      if (d2 < best) {
        best = d2;
        towards = q - a.state.x;
      }
    }
  }
  const double length = towards.norm();
  return length > 0.0 ? Eigen::Vector3d(towards / length) : Eigen::Vector3d::UnitZ();
}

BallSide ball_side(const Body &body) {
  return {body.triangles, body.spheres, body.pose.x, Eigen::Quaterniond(body.pose.q),
          body.epsilon};
}

} // namespace

std::size_t InteractionScratch::bytes() const {
  const ReductionWorkspace &r = reduction;
  std::size_t ints = r.parent.capacity() + r.order.capacity() + r.label.capacity() +
                     r.cls.capacity() + r.absorbed.capacity() + r.seeds.capacity() +
                     r.alive.capacity() + r.group.capacity() + r.tally.capacity();
  return distance.bytes() + points.capacity() * sizeof(ContactPoint) +
         records.capacity() * sizeof(ContactRecord) +
         r.raw.capacity() * sizeof(ReductionWorkspace::Raw) +
         r.keys.capacity() * sizeof(ReductionWorkspace::Key) +
         r.polygons.capacity() * sizeof(ContactPolygon) +
         r.points.capacity() * sizeof(Eigen::Vector3d) +
         (r.normals_a.capacity() + r.normals_b.capacity()) *
             sizeof(ReductionWorkspace::TriangleNormal) +
         ints * sizeof(int) + wall_apart.capacity() +
         4 * wall_planes.n_x.capacity() * sizeof(double);
}

namespace {

// The unit normal (outward for a closed, outward-oriented surface) of the triangle of `t`
// whose centroid is nearest `p`; zero for no triangles.
Eigen::Vector3d nearest_face_normal(const TriangleSoA &t, const Eigen::Vector3d &p) {
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (int k = 0; k < t.num_triangles(); ++k) {
    const Eigen::Vector3d v0 = t.vertex(k, 0), v1 = t.vertex(k, 1), v2 = t.vertex(k, 2);
    const double d2 = ((v0 + v1 + v2) / 3.0 - p).squaredNorm();
    if (d2 < best) {
      best = d2;
      normal = (v1 - v0).cross(v2 - v0);
    }
  }
  return normal;
}

// A new axis for the cache after a full search without contacts, the first of these that
// proves the gap: between the closest points of the triangle pairs it tested; between the
// centres; against the face of b nearest a's centre; along the face of a nearest b's centre
// (a particle over a wall patch: the patch's normal). Zero if none does; `gap` receives the
// gap the returned axis proves (proven_gap; its rounding slack covers the axis's
// normalisation).
Eigen::Vector3d new_separating_axis(const Body &a, const Body &b, double cutoff,
                                    const TrianglePairDistance *tested, int num_tested,
                                    double &gap) {
  const TriangleSoA &ta = *a.triangles, &tb = *b.triangles;
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d closest = Eigen::Vector3d::Zero();
  for (int k = 0; k < num_tested; ++k) {
    const TrianglePairDistance &r = tested[k];
    if (r.distance < best && r.distance > 0.0) {
      best = r.distance;
      closest = r.point_b - r.point_a;
    }
  }
  const Eigen::Vector3d centres = b.state.x - a.state.x;
  for (const Eigen::Vector3d &axis : {closest, centres}) {
    if (separated_along(ta, tb, axis, cutoff, &gap))
      return axis.normalized();
  }
  const Eigen::Vector3d face_b = -nearest_face_normal(tb, a.state.x);
  if (separated_along(ta, tb, face_b, cutoff, &gap))
    return face_b.normalized();
  const Eigen::Vector3d face_a = nearest_face_normal(ta, b.state.x);
  if (separated_along(ta, tb, face_a, cutoff, &gap))
    return face_a.normalized();
  return Eigen::Vector3d::Zero();
}

// Marks in scratch.wall_apart the triangles of `wall` whose plane has all of `particle`'s
// vertices more than `margin` (plus separating_axis.h's slack) on one side; true if every
// triangle's plane has them more than `cutoff` (<= margin) beyond. O(wall triangles x particle
// vertices).
bool walls_apart_by_planes(const TriangleSoA &particle, const TriangleSoA &wall, double cutoff,
                           double margin, InteractionScratch &scratch) {
  const int n = wall.num_triangles();
  scratch.wall_apart.assign(static_cast<std::size_t>(n), 0);
  compute_triangle_planes(wall, scratch.wall_planes);
  const TrianglePlanes &p = scratch.wall_planes;
  const double wall_magnitude = soa_extent(wall, Eigen::Vector3d::UnitX()).magnitude;
  int apart = 0;
  for (int t = 0; t < n; ++t) {
    const Eigen::Vector3d normal(p.n_x[t], p.n_y[t], p.n_z[t]);
    if (normal == Eigen::Vector3d::Zero())
      continue;
    const Extent e = soa_extent(particle, normal);
    const double slack = kSeparationSlackRatio * (e.magnitude + wall_magnitude + std::fabs(margin));
    const double gap = std::max(e.lo - p.offset[t], p.offset[t] - e.hi);
    scratch.wall_apart[t] = gap >= margin + slack;
    apart += gap >= cutoff + slack;
  }
  return n > 0 && apart == n;
}

// The distance between the two bodies' contact surfaces at which triangles count as touching:
// each body's reach against the other.
double contact_cutoff(const Body &a, const Body &b) {
  return a.reach_epsilon(b) + b.reach_epsilon(a);
}

const RigidPose *pose_of_b(const Body &b) { return b.is_wall() ? nullptr : &b.pose; }

// A body whose extents come from its pose (a radius is what bounds its world coordinates).
bool posed(const Body &body) { return body.frame && body.pose.radius > 0.0; }

// A gap proven between a and b now, kept for the travel proof: two particles only (a wall
// patch has no pose to bound its vertices' magnitude, and hosts keep no travel for it).
void keep_travel(const Body &a, const Body &b, CandidateCache &kept, const Travel &travel,
                 double gap) {
  if (travel.epoch == 0 || b.is_wall())
    return;
  kept.keep_travel(travel, gap,
                   CandidateCache::magnitude_of(a.pose) + CandidateCache::magnitude_of(b.pose));
}

// The vertices a body's extents are computed from: body frame where it has a pose.
const TriangleSoA &extent_vertices(const Body &body) {
  return posed(body) ? *body.frame : *body.triangles;
}

// A body's vertices along a unit world direction.
Extent body_extent(const Body &body, const Eigen::Vector3d &n) {
  if (posed(body))
    return posed_extent(*body.frame, body.pose.q, body.pose.x, body.pose.radius, n);
  return soa_extent(*body.triangles, n);
}

} // namespace

double candidate_reach(const Body &a, const Body &b, double coherence, double cutoff,
                       double dt) {
  const double rate = (b.state.v - a.state.v).norm() + a.state.omega.norm() * a.pose.radius +
                      b.state.omega.norm() * b.pose.radius;
  const double motion = kCandidateSteps * rate * dt;
  const double reach = std::max(coherence * cutoff, std::min(motion, kCandidateReachCap * cutoff));
  return std::isfinite(reach) ? reach : coherence * cutoff;
}

bool proven_apart(const Body &a, const Body &b, const InteractionSettings &s,
                  SeparationCache cache) {
  // Only a pair with a kept axis can be proven apart: a gap is kept beside an axis and dropped
  // with it (update_separation_cache), so most pairs in contact stop here, at the host's
  // history values.
  if (!cache.axis || (cache.axis[0] == 0.0 && cache.axis[1] == 0.0 && cache.axis[2] == 0.0))
    return false;
  const double cutoff = contact_cutoff(a, b);
  const RigidPose *pose_a = &a.pose, *pose_b = pose_of_b(b);
  CandidateCache *kept = s.coherence > 0.0 ? cache.candidates : nullptr;
  // The travel proof (O(1) on the host's sums), then a gap kept from an earlier step that the
  // motion since cannot have closed (O(1); a rigid pose's triangles are not read), then the kept
  // axis (O(vertices)). A gap proven now is kept for the travel proof.
  if (proven_apart_by_travel(kept, cache.travel, cutoff))
    return true;
  double proven = 0.0;
  if (kept && kept->proves_apart(pose_a, *a.triangles, pose_b, *b.triangles, cutoff, &proven)) {
    if (cache.update)
      keep_travel(a, b, *kept, cache.travel, proven);
    return true;
  }
  const Eigen::Vector3d axis(cache.axis);
  const double length = axis.norm();
  if (!(length > 0.0) || !std::isfinite(length) || extent_vertices(a).x.empty() ||
      extent_vertices(b).x.empty())
    return false;
  const Eigen::Vector3d n = axis / length;
  const double gap = proven_gap(body_extent(a, n), body_extent(b, n), cutoff);
  if (!(gap >= cutoff))
    return false;
  if (kept && cache.update) {
    kept->keep_gap(pose_a, *a.triangles, pose_b, *b.triangles, gap, n);
    keep_travel(a, b, *kept, cache.travel, gap);
  }
  return true;
}

bool proven_apart_by_travel(const CandidateCache *kept, const Travel &travel, double cutoff) {
  return kept && kept->proves_apart_by_travel(travel, cutoff);
}

PairForceResult apart_result(const Body &a, const Body &b, const InteractionSettings &s,
                             double dt, double *history, InteractionScratch &scratch,
                             ContactStats &stats) {
  // exactly what the search returns for a pair without contacts
  ++stats.bodies_separated;
  scratch.points.clear();
  return pair_contact_force(scratch.points, a.state, b.state, s.coefficients, dt, history);
}

bool apart_needs_nothing(const double *stored_history) {
  // The history is written compactly (contact_history.h): slot 0 holds the first contact's unit
  // normal, and with no contact every value is zero. So an empty slot 0 is a clear history,
  // read from its first cache line rather than all five (-0.0 counts as empty: the flipped
  // view writes it back for a cleared value).
  return !stored_history || !slot_occupied(stored_history, 0);
}

PairForceResult apart_result(ContactStats &stats) {
  // pair_contact_force of no contacts: the zero result
  ++stats.bodies_separated;
  return PairForceResult{};
}

namespace {

// The kept axis and gap after a search or a kept list has been run: a new axis (and gap) where
// no triangle pair touches and one proves the gap, else none. `tested`: the kernel's results on
// all `num_tested` candidates.
void update_separation_cache(const Body &a, const Body &b, const InteractionSettings &s,
                             SeparationCache cache, bool touching,
                             const TrianglePairDistance *tested, int num_tested) {
  if (!cache.axis || !cache.update)
    return;
  const double cutoff = contact_cutoff(a, b);
  CandidateCache *kept = s.coherence > 0.0 ? cache.candidates : nullptr;
  double gap = -std::numeric_limits<double>::infinity();
  const Eigen::Vector3d axis = !touching
                                   ? new_separating_axis(a, b, cutoff, tested, num_tested, gap)
                                   : Eigen::Vector3d::Zero();
  for (int d = 0; d < 3; ++d)
    cache.axis[d] = axis[d];
  if (kept && axis == Eigen::Vector3d::Zero())
    kept->clear_gap();
  if (kept && axis != Eigen::Vector3d::Zero()) {
    const Eigen::Vector3d n = axis / axis.norm(); // the direction proven_gap projects on
    kept->keep_gap(&a.pose, *a.triangles, pose_of_b(b), *b.triangles, gap, n);
    keep_travel(a, b, *kept, cache.travel, gap);
  }
}

// Whether a measurement of this pair keeps its points for the next step (kept_contacts.h).
bool keeps_contacts(const Body &b, const InteractionSettings &s, const SeparationCache &cache) {
  return cache.kept_contacts && cache.update && s.kept_tolerance > 0.0 &&
         (!b.is_wall() || b.triangle_ids);
}

// How the pair's triangle contacts become contact points (contact_reduction.h).
ReductionParams reduction_params(const Body &a, const Body &b, const InteractionSettings &s,
                                 bool classify) {
  ReductionParams params;
  params.method = s.reduction;
  params.link_length =
      recommended_link_length(a.longest_edge, b.longest_edge, a.epsilon, b.epsilon);
  params.min_width = std::min(a.min_edge, b.min_edge);
  params.reference_direction = reference_direction(a, b);
  params.distance_tolerance = certified_tolerance(s.distance, a.epsilon, b.epsilon);
  params.classify = classify;
  // Two particles of which one is not convex, or a particle and a wall (a crease of its
  // facets), may touch in several spots (contact_reduction.h, step 2); two convex particles
  // touch in one.
  if (a.is_wall() || b.is_wall() || !(a.convex && b.convex))
    params.distinct_spot_distance = a.epsilon + b.epsilon;
  // Smooth surfaces against facets (a wall, a cube's face, a rock): measured on the smooth
  // one. Between two smooth surfaces the peak measured along each facet pair's bisector did not
  // conserve energy (validation/contact/deep, pairs: e 0.976 undamped), so two balls meet as
  // their spheres instead (ball_contacts, after the reduction), and other pairs of smooth
  // surfaces keep their facets.
  if (a.is_ball() && b.is_ball()) {
    params.surface_lift = a.ball_lift + b.ball_lift;
    params.keep_shallow = true;
  } else if (smooth_on_facets(a, b)) {
    params.edge_bulge_a = a.edge_bulge;
    params.edge_bulge_b = b.edge_bulge;
    params.surface_lift = a.lift + b.lift;
  }
  return params;
}

// What follows the distance kernel (`tested`: its results on all the pair's triangle pairs
// `pairs`; the `num_contacts` of them closer than the cutoff are the triangle contacts, read in
// place): the kept axis, the reduction, the force.
PairForceResult forces_from_contacts(const Body &a, const Body &b, const InteractionSettings &s,
                                     double dt, double *history, InteractionScratch &scratch,
                                     SeparationCache cache, const TrianglePairIndex *pairs,
                                     const TrianglePairDistance *tested, int num_tested,
                                     int num_contacts) {
  const bool touching = num_contacts > 0;
  update_separation_cache(a, b, s, cache, touching, tested, num_tested);
  const bool keep = keeps_contacts(b, s, cache);
  if (!touching) { // the reduction of nothing needs no parameters
    scratch.points.clear();
    if (keep && kept_state(cache.kept_contacts))
      clear_kept_contacts(cache.kept_contacts);
    return pair_contact_force(scratch.points, a.state, b.state, s.coefficients, dt, history);
  }
  // Points to be kept are classified whether or not this step records them: a record of a
  // carried point must say what a measured one would.
  const bool keep_now = keep && keep_after_measuring(cache.kept_contacts);
  const ReductionParams params = reduction_params(a, b, s, scratch.record_contacts || keep_now);
  reduce_kernel_results(pairs, tested, num_tested, contact_cutoff(a, b), *a.triangles, a.epsilon,
                        *b.triangles, b.epsilon, params, scratch.reduction, scratch.points);
  const double layer = a.epsilon + b.epsilon;
  SurfaceSide side_a, side_b;
  side_b.wall = b.is_wall();
  side_b.particle_centre = a.state.x;
  deepen_contacts(*a.triangles, side_a, *b.triangles, side_b, layer, params.reference_direction,
                  params.link_length, scratch.points, scratch.depth);
  place_between_given_surfaces(a.epsilon, b.epsilon, scratch.points);
  if (params.keep_shallow)
    ball_contacts(ball_side(a), ball_side(b), scratch.points);
  if (keep_now)
    keep_contacts(a.pose, b.pose, scratch.points, cache.kept_contacts, b.triangle_ids);
  PairForceResult r = pair_contact_force(scratch.points, a.state, b.state, s.coefficients, dt,
                                         history,
                                         scratch.record_contacts ? &scratch.records : nullptr);
  r.layer = layer;
  r.depth_limit = deep_contact_limit(a.thinnest, b.thinnest);
  return r;
}

// From the kernel's results on the pair's `count` candidates `pairs` (whoever ran it): the
// contacts counted, the candidates kept or rebased, then the forces.
PairForceResult forces_from_results(const Body &a, const Body &b, const InteractionSettings &s,
                                    double dt, double *history, InteractionScratch &scratch,
                                    ContactStats &stats, SeparationCache cache, CandidateList list,
                                    double reach, const TrianglePairIndex *pairs,
                                    const TrianglePairDistance *results, int count) {
  const double cutoff = contact_cutoff(a, b);
  const int num_contacts = count_triangle_contacts(results, count, cutoff);
  stats.contacts += num_contacts;
  if (list == CandidateList::kept)
    cache.candidates->rebase(&a.pose, *a.triangles, pose_of_b(b), *b.triangles, results);
  else if (list == CandidateList::searched_to_keep)
    cache.candidates->keep(&a.pose, *a.triangles, pose_of_b(b), *b.triangles, cutoff, reach, pairs,
                           count, results);
  return forces_from_contacts(a, b, s, dt, history, scratch, cache, pairs, results, count,
                              num_contacts);
}

// The kernel request for the pair's candidates pairs[0, count). `lower`, `skip_from`: kept
// candidates' bounds (HybridJob).
KernelRequest kernel_request(const Body &a, const Body &b, const InteractionSettings &s,
                             ContactStats &stats, CandidateList list, double reach,
                             const TrianglePairIndex *pairs, int count, const double *lower,
                             double skip_from) {
  return KernelRequest{queue_candidates(*a.triangles, a.reach_epsilon(b), *b.triangles,
                                        b.reach_epsilon(a), s.distance, pairs, count, stats, lower,
                                        skip_from),
                       list, reach};
}

// The kernel run at once on the pair's candidates pairs[0, count), and the result. The kernels
// that cannot be queued run every pair: kept bounds are of no use to them.
PairForceResult run_kernel_at_once(const Body &a, const Body &b, const InteractionSettings &s,
                                   double dt, double *history, InteractionScratch &scratch,
                                   ContactStats &stats, SeparationCache cache, CandidateList list,
                                   double reach, const TrianglePairIndex *pairs, int count) {
  distances_among_candidates(*a.triangles, a.reach_epsilon(b), *b.triangles, b.reach_epsilon(a),
                             s.distance, pairs, count, stats, scratch.distance);
  return forces_from_results(a, b, s, dt, history, scratch, stats, cache, list, reach, pairs,
                             scratch.distance.results.data(), count);
}

// The kept candidates of a pair whose list still covers the bodies (candidate_cache.h).
PairPlan plan_kept_candidates(const Body &a, const Body &b, const InteractionSettings &s, double dt,
                              double *history, InteractionScratch &scratch, ContactStats &stats,
                              SeparationCache cache) {
  CandidateCache &kept = *cache.candidates;
  ++stats.candidates_kept;
  if (cache.update)
    kept.note_use();
  // The kernel skips the kept pairs the motion cannot have brought within the cutoff.
  const double skip =
      kept.skip_from(&a.pose, *a.triangles, pose_of_b(b), *b.triangles, contact_cutoff(a, b));
  if (can_queue_candidates(s.distance, kept.count()))
    return kernel_request(a, b, s, stats, CandidateList::kept, 0.0, kept.pairs(), kept.count(),
                          kept.lower_bounds(), skip);
  return run_kernel_at_once(a, b, s, dt, history, scratch, stats, cache, CandidateList::kept, 0.0,
                            kept.pairs(), kept.count());
}

// A fresh search: its candidates kept where `keep` (for a coherent pair worth it) with the
// reach of candidate_reach.
PairPlan plan_search(const Body &a, const Body &b, const InteractionSettings &s, double dt,
                     double *history, InteractionScratch &scratch, ContactStats &stats,
                     SeparationCache cache, bool keep) {
  const double cutoff = contact_cutoff(a, b);
  const double reach = keep ? candidate_reach(a, b, s.coherence, cutoff, dt) : 0.0;
  const double margin = cutoff + reach;
  // A wall patch: its triangles whose plane a lies beyond (either side) cannot touch a; if
  // that is all of them, a touches nothing, also where no single axis separates a from the
  // patch (a floor and a side wall around the particle).
  const std::uint8_t *skip = nullptr;
  if (b.is_wall() && s.distance.cull && s.distance.tight_cull) {
    if (walls_apart_by_planes(*a.triangles, *b.triangles, cutoff, margin, scratch))
      return apart_result(a, b, s, dt, history, scratch, stats);
    skip = scratch.wall_apart.data();
  }
  const int count =
      find_candidate_pairs(*a.triangles, *b.triangles, margin, s.distance, scratch.distance, skip);
  const CandidateList list = keep ? CandidateList::searched_to_keep : CandidateList::searched;
  const TrianglePairIndex *found = scratch.distance.pairs.data();
  if (count > 0 && can_queue_candidates(s.distance, count))
    return kernel_request(a, b, s, stats, list, reach, found, count, nullptr,
                          std::numeric_limits<double>::infinity());
  return run_kernel_at_once(a, b, s, dt, history, scratch, stats, cache, list, reach, found, count);
}

} // namespace

bool kept_contacts_hold(const Body &a, const Body &b, const InteractionSettings &s,
                        const SeparationCache &cache) {
  if (!cache.kept_contacts || !(s.kept_tolerance > 0.0) || a.is_wall() ||
      (b.is_wall() && !b.triangle_ids))
    return false;
  if (kept_contacts_motion(cache.kept_contacts, a.pose, b.pose) >
      s.kept_tolerance * (a.epsilon + b.epsilon))
    return false;
  return !b.triangle_ids || kept_triangles_present(cache.kept_contacts, b.triangle_ids,
                                                   b.triangles->num_triangles());
}

PairForceResult carried_contacts_result(const Body &a, const Body &b, const InteractionSettings &s,
                                        double dt, double *history, InteractionScratch &scratch,
                                        ContactStats &stats, const SeparationCache &cache) {
  ++stats.contacts_carried;
  if (cache.update)
    mark_carried(cache.kept_contacts);
  carry_kept_contacts(cache.kept_contacts, a.pose, b.pose, scratch.points, b.triangle_ids,
                      b.triangle_ids ? b.triangles->num_triangles() : 0);
  PairForceResult r = pair_contact_force(scratch.points, a.state, b.state, s.coefficients, dt,
                                         history,
                                         scratch.record_contacts ? &scratch.records : nullptr);
  r.layer = a.epsilon + b.epsilon;
  r.depth_limit = deep_contact_limit(a.thinnest, b.thinnest);
  return r;
}

PairPlan plan_body_pair(const Body &a, const Body &b, const InteractionSettings &s, double dt,
                        double *history, InteractionScratch &scratch, ContactStats &stats,
                        SeparationCache cache) {
  if (kept_contacts_hold(a, b, s, cache))
    return carried_contacts_result(a, b, s, dt, history, scratch, stats, cache);
  // Kept candidates replace the search (candidate_cache.h); not with the batched kernel, whose
  // result for a pair depends on its batch.
  CandidateCache *kept = s.coherence > 0.0 ? cache.candidates : nullptr;
  const bool coherent =
      kept && s.distance.cull && s.distance.kernel != DistanceKernel::BatchedHybrid;
  if (coherent &&
      kept->covers(&a.pose, *a.triangles, pose_of_b(b), *b.triangles, contact_cutoff(a, b)))
    return plan_kept_candidates(a, b, s, dt, history, scratch, stats, cache);
  const bool keep = coherent && cache.update && kept->worth_keeping();
  return plan_search(a, b, s, dt, history, scratch, stats, cache, keep);
}

PairForceResult finish_body_pair(const Body &a, const Body &b, const InteractionSettings &s,
                                 double dt, double *history, InteractionScratch &scratch,
                                 ContactStats &stats, SeparationCache cache,
                                 const KernelRequest &request,
                                 const TrianglePairDistance *results) {
  return forces_from_results(a, b, s, dt, history, scratch, stats, cache, request.candidates,
                             request.reach, request.job.pairs, results, request.job.count);
}

} // namespace tri
