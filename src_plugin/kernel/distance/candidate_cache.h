// Triangle-pair candidates kept between steps for one body pair: temporal coherence.
// Bodies in contact, in a pile above all, barely move from one step to the next, yet
// the cull (boxes in two frames, then the separating-axis test of each surviving triangle
// pair) would rebuild the same short list every step. Instead the list is built once with a
// wider margin, cutoff + reach, and reused while the bodies cannot have moved far enough for a
// pair outside it to come within the cutoff.
//
// Proof. Every point of a triangle is a convex combination of its vertices, so it moves no
// farther than its farthest vertex; the distance of two triangles therefore changes by at
// most D_a + D_b, D the largest displacement of a body's vertices since the list was built.
// The list holds every pair closer than cutoff + reach then (the cull keeps every pair closer
// than its margin, triangle_boxes.h), so while D_a + D_b + slack < reach every pair now closer
// than the cutoff is in it (pairs whose certified lower bound was already beyond cutoff + reach
// are left out: they cannot be). The distance kernel treats each pair on its own
// (particle_contacts.h), so the contacts are exactly those of a full search, bit for bit, in
// the same order; only which pairs are tested beyond the cutoff differs.
//
// D of a rigid particle (world vertex R p + x, |p| <= bounding radius r in its body frame):
//   D <= |x - x0| + |R - R0| r = |x - x0| + 2 sin(theta / 2) r,
// theta the angle of the rotation R R0^T; for unit quaternions sin(theta / 2) is the length of
// the vector part of q q0^* (either sign of q). For two particles the distance of two
// triangles depends only on where each body is relative to the other, so D_a + D_b may be
// replaced by their relative motion, the smaller of the two bounds (relative_motion_bound,
// rigid_pose.h): b's vertices seen from a's frame move by at most |t - t0| + 2 sin(theta / 2)
// r_b, (t, theta) b's centre in a's frame and its turn relative to a. In a flowing bed, where
// neighbours move together, that keeps a list for many steps where the sum of the two bodies'
// own motions used it up in a few (the formed hopper: 118 searches a step instead of 264, 52
// with kCandidateSteps' longer reach). D of a wall patch (no body frame; the host gathers its
// triangles afresh each step): the largest displacement of its vertices, listed in the same
// order, which also catches a patch whose triangles changed (then the count differs, or a
// vertex jumps). Rounding: the world vertices and the bound carry errors of a few ulps of the
// coordinates; the slack, kSeparationSlackRatio (separating_axis.h) times the magnitudes, is
// orders of magnitude above them.
//
// The same bound thins the list from step to step. Each kept pair carries a lower bound l on
// its distance at reference poses of the bodies: its certified lower bound from the distance
// kernel (distance_kernels.h) when it last ran. Its distance now is at least l - D', D' the
// motion since those poses (the bound above, slack included), so a pair with
// l >= cutoff + D' (skip_from) cannot be in contact, and the kernel skips it (HybridJob::lower).
// After the kernel, rebase() moves every bound to the current poses: a pair that ran takes its
// new lower bound, a skipped one l - D'. So a pair just beyond the cutoff runs again only once
// the motion since it last ran could have closed its margin, not every step the list is used:
// in the formed hopper 46 % of the kept pairs a step were beyond the cutoff, in the settled
// pile 29 %. The contacts are the same, in the same order: a skipped pair is not one.
//
// The same bound keeps a proof of separation: a gap g proven between the bodies along a unit
// separating axis n (from a towards b, separating_axis.h) is g = min_b n.q - max_a n.p. A
// vertex of a rigid particle moves by (x - x0) + (R - R0) p, so its projection on n changes by
// n.(x - x0) plus at most 2 sin(theta / 2) r: the translation counts only along the axis, and
// with its sign (a pair drifting apart keeps its proof). A wall patch's vertices are compared
// one by one, projected on n. So while
//   g - [n.(x_a - x_a0) + rot_a] - [-n.(x_b - x_b0) + rot_b] - slack >= cutoff
// the bodies are still apart, in O(1) for particles, without projecting their vertices again
// (a gap kept without its axis falls back to g - D_a - D_b). In a granular gas, where bodies
// pass each other at speed, the proof lasts several times longer than with D_a + D_b.
//
// A cheaper proof of the same gap, for two particles: the host keeps, per particle, a running
// sum T of the bound above, T += |x - x'| + 2 sin(theta' / 2) r from the pose at its last update
// to the current one (rigid_motion_bound; Travel, restarted whenever the host renumbers its
// atoms: an epoch). Every vertex has moved at most T - T0 since a moment when T was T0 (triangle
// inequality over the updates), so a gap g proven at that moment still holds, less the travel
// since, while
//   g - (T_a - T_a0) - (T_b - T_b0) - slack >= cutoff.
// Two subtractions and a compare on values the host has at hand: a pile's neighbour pairs that
// stay apart for many steps (most of them) are passed over without their poses, their kept gap
// or their history being read (keep_travel / proves_apart_by_travel). The bound is looser than
// the kept gap's (it gives no credit for motion away along the axis, and sums the path rather
// than the displacement); where it fails the kept gap is tried as before. Rounding: the travel
// is a sum of non-negative terms, each within a few ulps; the slack is kSeparationSlackRatio
// times the coordinates' magnitude when the gap was proven plus twice the travel since, and the
// gap; as for the kept gap, orders of magnitude above the rounding.
//
// The kept list is the host's (one per body pair, pair tri/gran and fix tri/wall); a list may
// be dropped at any time (neighbour-list rebuild, migration, restart): the next step searches
// afresh, and the contacts are the same either way.
#pragma once

#include "body/rigid_pose.h"
#include "distance/distance_kernels.h"
#include "distance/separating_axis.h"
#include "distance/triangle_distance.h"
#include "geometry/triangle_soa.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tri {

// The host's running sums of the two bodies' vertex motion (m) in one epoch (header); epoch 0:
// not kept (a wall patch, a ghost atom, a host that keeps none).
struct Travel {
  double a = 0.0, b = 0.0;
  long long epoch = 0;
};

class CandidateCache {
public:
  // True when the kept list still holds every pair of the bodies now closer than `cutoff`:
  // a list exists, was built for this cutoff, and the motion since then is within its reach.
  // `pose_a`, `pose_b`: null for a wall patch (its vertices `b` are compared instead).
  bool covers(const RigidPose *pose_a, const TriangleSoA &a, const RigidPose *pose_b,
              const TriangleSoA &b, double cutoff) const;

  // The kept pairs, and per pair a lower bound on its distance at the reference poses (header).
  const TrianglePairIndex *pairs() const { return pairs_.data(); }
  const double *lower_bounds() const { return lower_.data(); }
  int count() const { return static_cast<int>(pairs_.size()); }
  // Once covers() holds: the bound from which on a kept pair cannot be within `cutoff` now,
  // cutoff plus the motion since the reference poses (+infinity: that motion is not bounded).
  double skip_from(const RigidPose *pose_a, const TriangleSoA &a, const RigidPose *pose_b,
                   const TriangleSoA &b, double cutoff);
  // After the distance kernel ran on the kept pairs (results[k] pair k's), moves the bounds to
  // the current poses (header). A pair the kernel skipped is told by its distance, +infinity
  // (HybridJob::lower); its other fields are not read. Whichever kernel ran, and whatever it
  // skipped, every bound stays a bound.
  void rebase(const RigidPose *pose_a, const TriangleSoA &a, const RigidPose *pose_b,
              const TriangleSoA &b, const TrianglePairDistance *results);

  // Keeps pairs[0, count), found with margin cutoff + reach, and the bodies' poses now; with
  // `results` (the distance kernel's on those pairs), only the pairs whose certified lower
  // bound is below cutoff + reach (plus the rounding slack): the others cannot come within the
  // cutoff while the list is used.
  void keep(const RigidPose *pose_a, const TriangleSoA &a, const RigidPose *pose_b,
            const TriangleSoA &b, double cutoff, double reach, const TrianglePairIndex *pairs,
            int count, const TrianglePairDistance *results = nullptr);

  // Whether a search should keep its list (with the wider margin). Not for a while after a list
  // that was never used: bodies that move more than the reach in one step (a collision, a fast
  // flow) would only pay the margin's extra pairs at every search. Tried again after
  // kPausedSearches searches. A heuristic on cost only: the contacts are the same either way.
  bool worth_keeping();
  void note_use() { ++uses_; }

  // True when a kept gap still proves every pair at least `cutoff` apart. With `proven`: the gap
  // it proves now (slack taken off).
  bool proves_apart(const RigidPose *pose_a, const TriangleSoA &a, const RigidPose *pose_b,
                    const TriangleSoA &b, double cutoff, double *proven = nullptr) const;
  // The travel proof (header): true when the gap kept with keep_travel, less the travel since,
  // is still at least `cutoff`. Reads only the entry's first fields (inline: a host calls it
  // for every neighbour pair while it lists them).
  bool proves_apart_by_travel(const Travel &now, double cutoff) const {
    if (now.epoch == 0 || now.epoch != travel_epoch_)
      return false;
    const double moved = (now.a - travel_a_) + (now.b - travel_b_);
    const double slack = kSeparationSlackRatio * (travel_magnitude_ + 2.0 * moved + travel_gap_);
    return travel_gap_ - moved - slack >= cutoff; // false for NaN
  }
  // Keeps `gap` (m), proven between two particles now, for proves_apart_by_travel: `travel`
  // their sums now, `magnitude` the largest coordinate of their vertices (m).
  void keep_travel(const Travel &travel, double gap, double magnitude) {
    travel_epoch_ = std::isfinite(gap) && std::isfinite(magnitude) ? travel.epoch : 0;
    travel_gap_ = gap;
    travel_a_ = travel.a;
    travel_b_ = travel.b;
    travel_magnitude_ = magnitude;
  }
  // The largest coordinate of a particle's vertices (its pose), for keep_travel.
  static double magnitude_of(const RigidPose &p) {
    return p.x.cwiseAbs().maxCoeff() + p.radius;
  }
  // Keeps `gap` (m), proven between the bodies now along `axis` (unit, from a towards b; zero:
  // not known, the motion is bounded in every direction), and their poses.
  void keep_gap(const RigidPose *pose_a, const TriangleSoA &a, const RigidPose *pose_b,
                const TriangleSoA &b, double gap,
                const Eigen::Vector3d &axis = Eigen::Vector3d::Zero());

  void clear() { valid_ = false; }
  // Drops the kept gap (its pair has lost its axis: body_interaction keeps a gap only beside an
  // axis, so a pair without one is never proven apart by a stale gap, and the hosts skip
  // such pairs without reading this entry).
  void clear_gap() {
    gap_valid_ = false;
    travel_epoch_ = 0;
  }
  // Asks for this entry's cache lines: a host's entries lie wherever its map put them, and a
  // task that waits for them (the poses compared first) stalls on every lookup.
  void prefetch() const {
    const char *p = reinterpret_cast<const char *>(this);
    for (std::size_t offset = 0; offset < sizeof(*this); offset += 64)
      __builtin_prefetch(p + offset);
  }
  std::size_t bytes() const; // heap memory held

private:
  // Where a body was: a particle by its rigid pose, a wall patch by its vertices.
  struct Pose {
    bool rigid = false;
    RigidPose pose;
    std::vector<double> vertices; // wall: x, y, z of each SoA vertex
  };
  static void record(const RigidPose *rigid, const TriangleSoA &t, Pose &out);
  // The bound D of the header on the body's vertex displacements, plus its magnitude M (the
  // largest coordinate, for the rounding slack); D = infinity if it cannot be bounded. With
  // `along` (unit): how far the vertices can have advanced along it instead (the largest
  // increase of along . p; negative: all receded).
  static double displacement(const Pose &then, const RigidPose *rigid, const TriangleSoA &t,
                             double &magnitude, const Eigen::Vector3d *along = nullptr);

  // The motion of both bodies since the poses a, b were recorded, plus the rounding slack:
  // D_a + D_b, or for two particles whose D_a + D_b is at least `relative_from` the smaller
  // of that and their relative motion (header). Either bounds the distances; the relative one
  // costs two relative poses, so a caller that a motion below relative_from already serves
  // (a settled pile's nanometres) does not pay for it.
  static double moved(const Pose &a, const RigidPose *pose_a, const TriangleSoA &ta, const Pose &b,
                      const RigidPose *pose_b, const TriangleSoA &tb, double length,
                      double relative_from = 0.0);
  // skip_from asks for the relative motion from this fraction of the cutoff on: a flowing
  // bed's particles move farther in a step (a few hundredths), a settled pile's far less.
  static constexpr double kSkipRelativeFrom = 1e-3;

  static constexpr int kPausedSearches = 8;
  // The travel proof first: with the store's key and step, one cache line (candidate_store.h).
  double travel_gap_ = 0.0, travel_a_ = 0.0, travel_b_ = 0.0, travel_magnitude_ = 0.0;
  long long travel_epoch_ = 0; // 0: none kept
  bool valid_ = false; // candidates kept
  int uses_ = 0;       // steps the kept list served
  int pause_ = 0;      // searches left that keep no list
  double cutoff_ = 0.0, reach_ = 0.0;
  Pose a_, b_;
  bool gap_valid_ = false; // a gap kept
  double gap_ = 0.0;
  Eigen::Vector3d gap_axis_ = Eigen::Vector3d::Zero(); // unit, a towards b; zero: not known
  Pose gap_a_, gap_b_;
  std::vector<TrianglePairIndex> pairs_;
  std::vector<double> lower_; // per kept pair: at the poses base_a_, base_b_ (-inf: not known), m
  Pose base_a_, base_b_;
  double base_motion_ = 0.0; // the motion since then, as skip_from bounded it
};

} // namespace tri
