#include "interaction/body_interaction.h"

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

} // namespace

std::size_t InteractionScratch::bytes() const {
  const ReductionWorkspace &r = reduction;
  std::size_t ints = r.parent.capacity() + r.order.capacity() + r.label.capacity() +
                     r.cls.capacity() + r.absorbed.capacity() + r.seeds.capacity() +
                     r.alive.capacity() + r.group.capacity() + r.tally.capacity();
  return distance.bytes() + triangle_contacts.capacity() * sizeof(TriangleContact) +
         points.capacity() * sizeof(ContactPoint) +
         records.capacity() * sizeof(ContactRecord) + r.raw.capacity() * sizeof(ReductionWorkspace::Raw) +
         r.keys.capacity() * sizeof(ReductionWorkspace::Key) +
         r.polygons.capacity() * sizeof(ContactPolygon) +
         r.points.capacity() * sizeof(Eigen::Vector3d) +
         (r.normals_a.capacity() + r.normals_b.capacity()) *
             sizeof(ReductionWorkspace::TriangleNormal) +
         ints * sizeof(int) + wall_apart.capacity() +
         4 * wall_planes.n_x.capacity() * sizeof(double) + jobs.capacity() * sizeof(HybridJob) +
         job_offsets.capacity() * sizeof(std::size_t) +
         job_origins.capacity() * sizeof(JobOrigin) +
         job_pairs.capacity() * sizeof(TrianglePairIndex) +
         job_results.capacity() * sizeof(TrianglePairDistance);
}

void InteractionScratch::run_jobs(HybridCounters &stats) {
  std::size_t total = 0;
  job_offsets.resize(jobs.size());
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    job_offsets[j] = total;
    total += static_cast<std::size_t>(jobs[j].count);
  }
  job_results.resize(total);
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    jobs[j].out = job_results.data() + job_offsets[j];
    if (job_origins[j].pairs_offset >= 0) // job_pairs has stopped growing: pointers now
      jobs[j].pairs = job_pairs.data() + job_origins[j].pairs_offset;
  }
  hybrid_distances_jobs(jobs.data(), static_cast<int>(jobs.size()), stats);
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

} // namespace

namespace {

// What follows the distance kernel (`tested`: its results on all the pair's triangle pairs
// `pairs`; the `num_contacts` of them closer than the cutoff are the triangle contacts, read in
// place): the kept axis, the reduction, the force.
PairForceResult after_kernel(const Body &a, const Body &b, const InteractionSettings &s,
                             double dt, double *history, InteractionScratch &scratch,
                             SeparationCache cache, const TrianglePairIndex *pairs,
                             const TrianglePairDistance *tested, int num_tested, int num_contacts);

// The second call for a pair whose job the engine ran (InteractionScratch::resume_job).
PairForceResult resume_after_kernel(const Body &a, const Body &b, const InteractionSettings &s,
                                    double dt, double *history, InteractionScratch &scratch,
                                    ContactStats &stats, SeparationCache cache) {
  const std::size_t j = static_cast<std::size_t>(scratch.resume_job);
  const HybridJob &job = scratch.jobs[j];
  const InteractionScratch::JobOrigin &origin = scratch.job_origins[j];
  const TrianglePairDistance *results = scratch.job_results.data() + scratch.job_offsets[j];
  const double cutoff = a.reach_epsilon(b) + b.reach_epsilon(a);
  const int num_contacts = count_triangle_contacts(results, job.count, cutoff);
  stats.contacts += num_contacts;
  if (origin.keep)
    cache.candidates->keep(&a.pose, *a.triangles, b.is_wall() ? nullptr : &b.pose, *b.triangles,
                           cutoff, origin.reach, job.pairs, job.count, results);
  else if (origin.pairs_offset < 0) // a kept list's
    cache.candidates->rebase(&a.pose, *a.triangles, b.is_wall() ? nullptr : &b.pose,
                             *b.triangles, results);
  return after_kernel(a, b, s, dt, history, scratch, cache, job.pairs, results, job.count,
                      num_contacts);
}

} // namespace

namespace {

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
  // with it (after_kernel), so most pairs in contact stop here, at the host's history values.
  if (!cache.axis || (cache.axis[0] == 0.0 && cache.axis[1] == 0.0 && cache.axis[2] == 0.0))
    return false;
  const double cutoff = a.reach_epsilon(b) + b.reach_epsilon(a);
  const RigidPose *pose_a = &a.pose, *pose_b = b.is_wall() ? nullptr : &b.pose;
  CandidateCache *kept = s.coherence > 0.0 ? cache.candidates : nullptr;
  // The travel proof (O(1) on the host's sums), then a gap kept from an earlier step that the
  // motion since cannot have closed (O(1); a rigid pose's triangles are not read), then the kept
  // axis (O(vertices)). A gap proven now is kept for the travel proof.
  if (kept && kept->proves_apart_by_travel(cache.travel, cutoff))
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

PairForceResult body_interaction(const Body &a, const Body &b, const InteractionSettings &s,
                                 double dt, double *history, InteractionScratch &scratch,
                                 ContactStats &stats, SeparationCache cache) {
  if (scratch.resume_job >= 0)
    return resume_after_kernel(a, b, s, dt, history, scratch, stats, cache);
  const double cutoff = a.reach_epsilon(b) + b.reach_epsilon(a);
  const RigidPose *pose_a = &a.pose, *pose_b = b.is_wall() ? nullptr : &b.pose;
  CandidateCache *kept = s.coherence > 0.0 ? cache.candidates : nullptr;
  auto apart = [&]() { return apart_result(a, b, s, dt, history, scratch, stats); };
  if (!cache.not_apart && proven_apart(a, b, s, cache))
    return apart();
  // Kept candidates that still cover the bodies replace the search (candidate_cache.h).
  const bool coherent =
      kept && s.distance.cull && s.distance.kernel != DistanceKernel::BatchedHybrid;
  scratch.triangle_contacts.clear();
  if (coherent && cache.candidates->covers(pose_a, *a.triangles, pose_b, *b.triangles, cutoff)) {
    ++stats.candidates_kept;
    if (cache.update)
      cache.candidates->note_use();
    // The kernel skips the kept pairs the motion cannot have brought within the cutoff.
    CandidateCache &kc = *cache.candidates;
    const double skip = kc.skip_from(pose_a, *a.triangles, pose_b, *b.triangles, cutoff);
    if (scratch.defer && can_queue_candidates(s.distance, kc.count())) {
      scratch.jobs.push_back(queue_candidates(*a.triangles, a.reach_epsilon(b), *b.triangles,
                                              b.reach_epsilon(a), s.distance, kc.pairs(),
                                              kc.count(), stats, kc.lower_bounds(), skip));
      scratch.job_origins.push_back({});
      return PairForceResult{};
    }
    contacts_among_candidates(*a.triangles, a.reach_epsilon(b), *b.triangles, b.reach_epsilon(a),
                              s.distance, kc.pairs(), kc.count(), scratch.triangle_contacts,
                              stats, scratch.distance, kc.lower_bounds(), skip);
    kc.rebase(pose_a, *a.triangles, pose_b, *b.triangles, scratch.distance.results.data());
    return after_kernel(a, b, s, dt, history, scratch, cache, kc.pairs(),
                        scratch.distance.results.data(), scratch.distance.tested,
                        static_cast<int>(scratch.triangle_contacts.size()));
  } else {
    const bool keep = coherent && cache.update && cache.candidates->worth_keeping();
    const double reach = keep ? candidate_reach(a, b, s.coherence, cutoff, dt) : 0.0;
    const double margin = cutoff + reach;
    // A wall patch: its triangles whose plane a lies beyond (either side) cannot touch a; if
    // that is all of them, a touches nothing, also where no single axis separates a from the
    // patch (a floor and a side wall around the particle).
    const std::uint8_t *skip = nullptr;
    if (b.is_wall() && s.distance.cull && s.distance.tight_cull) {
      if (walls_apart_by_planes(*a.triangles, *b.triangles, cutoff, margin, scratch))
        return apart();
      skip = scratch.wall_apart.data();
    }
    const int count =
        find_candidate_pairs(*a.triangles, *b.triangles, margin, s.distance, scratch.distance, skip);
    if (count > 0 && scratch.defer && can_queue_candidates(s.distance, count)) {
      // The search's list is overwritten by the next task's: a copy, pointed at in run_jobs.
      const TrianglePairIndex *found = scratch.distance.pairs.data();
      scratch.job_origins.push_back(
          {static_cast<std::ptrdiff_t>(scratch.job_pairs.size()), keep, reach});
      scratch.job_pairs.insert(scratch.job_pairs.end(), found, found + count);
      scratch.jobs.push_back(queue_candidates(*a.triangles, a.reach_epsilon(b), *b.triangles,
                                              b.reach_epsilon(a), s.distance, nullptr, count,
                                              stats));
      return PairForceResult{};
    }
    contacts_among_candidates(*a.triangles, a.reach_epsilon(b), *b.triangles, b.reach_epsilon(a),
                              s.distance, scratch.distance.pairs.data(), count,
                              scratch.triangle_contacts, stats, scratch.distance);
    if (keep)
      cache.candidates->keep(pose_a, *a.triangles, pose_b, *b.triangles, cutoff, reach,
                             scratch.distance.pairs.data(), count, scratch.distance.results.data());
  }
  return after_kernel(a, b, s, dt, history, scratch, cache, scratch.distance.pairs.data(),
                      scratch.distance.results.data(), scratch.distance.tested,
                      static_cast<int>(scratch.triangle_contacts.size()));
}

namespace {

PairForceResult after_kernel(const Body &a, const Body &b, const InteractionSettings &s,
                             double dt, double *history, InteractionScratch &scratch,
                             SeparationCache cache, const TrianglePairIndex *pairs,
                             const TrianglePairDistance *tested, int num_tested,
                             int num_contacts) {
  const double cutoff = a.reach_epsilon(b) + b.reach_epsilon(a);
  const RigidPose *pose_a = &a.pose, *pose_b = b.is_wall() ? nullptr : &b.pose;
  CandidateCache *kept = s.coherence > 0.0 ? cache.candidates : nullptr;
  const bool touching = num_contacts > 0;
  if (cache.axis && cache.update) {
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
      kept->keep_gap(pose_a, *a.triangles, pose_b, *b.triangles, gap, n);
      keep_travel(a, b, *kept, cache.travel, gap);
    }
  }
  if (!touching) { // the reduction of nothing needs no parameters
    scratch.points.clear();
    return pair_contact_force(scratch.points, a.state, b.state, s.coefficients, dt, history);
  }

  ReductionParams params;
  params.method = s.reduction;
  params.link_length =
      recommended_link_length(a.longest_edge, b.longest_edge, a.epsilon, b.epsilon);
  params.min_width = std::min(a.min_edge, b.min_edge);
  params.reference_direction = reference_direction(a, b);
  params.distance_tolerance = certified_tolerance(s.distance, a.epsilon, b.epsilon);
  params.classify = scratch.record_contacts;
  // Smooth surfaces against walls only, for now: between two smooth balls the peak measured
  // along each facet pair's bisector did not conserve energy (validation/contact/deep, pairs:
  // e 0.976 undamped), so particle pairs keep their facets.
  if (b.is_wall()) {
    params.edge_bulge_a = a.edge_bulge;
    params.surface_lift = a.lift;
  }
  reduce_kernel_results(pairs, tested, num_tested, cutoff, *a.triangles, a.epsilon, *b.triangles,
                        b.epsilon, params, scratch.reduction, scratch.points);
  const double layer = a.epsilon + b.epsilon;
  SurfaceSide side_a, side_b;
  side_b.wall = b.is_wall();
  side_b.particle_centre = a.state.x;
  deepen_contacts(*a.triangles, side_a, *b.triangles, side_b, layer, params.reference_direction,
                  params.link_length, scratch.points, scratch.depth);
  place_between_given_surfaces(a.epsilon, b.epsilon, scratch.points);
  PairForceResult r = pair_contact_force(scratch.points, a.state, b.state, s.coefficients, dt,
                                         history,
                                         scratch.record_contacts ? &scratch.records : nullptr);
  r.layer = layer;
  r.depth_limit = deep_contact_limit(a.thinnest, b.thinnest);
  return r;
}

} // namespace

} // namespace tri
