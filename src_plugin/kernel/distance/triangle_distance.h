// Brute-force distance between two triangles: the paper's 15 checks (6 point-face, 9
// edge-edge) plus an intersection test. It is the reference against which the penalty and
// hybrid kernels are tested, and the fallback of the hybrid.
//
// Input: three vertices per triangle, any orientation, in any length unit (results are in
// the same unit). Degenerate input is allowed: sliver triangles (doubled area below
// kSliverRatio * longest edge^2, distance_primitives.h) are treated as their three edges,
// zero-length edges as points.
//
// Result (TrianglePairDistance):
// - separated triangles: distance > 0, point_a / point_b the closest points (on a / on b),
//   normal = (point_b - point_a) / distance. Where closest points are not unique (parallel
//   edges or faces) a valid pair is returned; the distance is exact up to rounding.
// - intersecting triangles (they share a point; touching counts): distance = 0,
//   intersecting = true, point_a = point_b = a point of both triangles (the mean of the
//   edge-face crossing points and of the closest pair of the checks when that pair
//   touches), normal and penetration_depth from min_overlap_axis (triangle_intersection.h).
// - touch tolerance: a pair whose checked distance is <= kTouchRatio * (longest edge of the
//   pair) is reported as touching (distance 0, intersecting); below that rounding decides.
// Accuracy: distance error <= 1e-12 * longest edge of the pair (measured <= ~1e-15) for
// regular triangles and for thin ones down to the sliver cut, at scales 1e-6 to 1e3: faces of
// height 1e-7 and 2e-8 of their length measure <= 1e-15 (test_triangle_distance_slivers.cpp;
// distance_primitives.h says how the face normal keeps that). Below the cut (slivers proper,
// doubled area < kSliverRatio * longest edge^2) additionally <= kSliverRatio * longest edge
// (the ignored width of the sliver).
#pragma once

#include "distance/triangle_pair_block.h"

#include <Eigen/Core>

namespace tri {

constexpr double kTouchRatio = 1e-12;

struct TrianglePairDistance {
  double distance = 0.0;            // >= 0, length unit of the input
  Eigen::Vector3d point_a, point_b; // closest points on a and on b
  Eigen::Vector3d normal;           // unit, from a towards b
  bool intersecting = false;        // the closed triangles share a point
  double penetration_depth = 0.0;   // intersecting only: separating translation along normal
  // A certified lower bound of the distance (rigorous up to rounding of the coordinates): the
  // distance itself from brute force, the penalty's separation bound (penalty_distance.h) from
  // the hybrid kernel; 0 where nothing is certified (penalty alone).
  double lower_bound = 0.0;
};

// Scalar reference: one pair, with branches.
TrianglePairDistance triangle_distance(const Eigen::Vector3d a[3], const Eigen::Vector3d b[3]);

// The distance of two triangles known not to intersect (a certified positive lower bound of
// their distance, penalty_distance.h), without the intersection test, closest points or
// normal: where a vertex of one lies over the other's face, nearer its plane than the rest of
// its triangle (the closest pair of most nearly parallel faces), that vertex's height; else
// the 15 checks. Equal to triangle_distance(a, b).distance to rounding wherever that is > 0;
// a negative value where the triangles touch (within kTouchRatio, where triangle_distance
// reports an intersection).
double separated_triangle_distance(const Eigen::Vector3d a[3], const Eigen::Vector3d b[3]);

// The same for the pairs in lanes 0..n-1 of a block (n <= kPairLanes; lanes n.. are
// ignored). The 15 checks and the intersection test run vectorised across all lanes; lanes
// that touch or intersect are finished by triangle_distance. Results are bit-identical to
// triangle_distance on the same pair (also when n <= kPairLanes / 2, where only the first half
// of the lanes runs).
void brute_force_block(const TrianglePairBlock &block, int n, TrianglePairDistance out[]);

// Floating-point operations of the vectorised part of brute_force_block per pair (15
// checks + 6 edge-face tests), counted by hand from distance_primitives.h; for the
// benchmark's GFLOP/s estimate only. (1220 before the edge normals of Face: per face
// +39 for the projected normal and m1..m3, per point-face or edge-face test -13.)
constexpr int kBruteForceFlopsPerPair = 1140;

} // namespace tri
