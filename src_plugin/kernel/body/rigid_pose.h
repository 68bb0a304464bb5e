// Where a rigid particle is, and how far its surface can have moved between two poses: the
// bound that lets a contact search keep what it found (distance/candidate_cache.h) and pass over
// pairs proven apart (the host's travel sums).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tri {

// The rigid pose of a particle whose world triangles are R(q) p + x with |p| <= radius.
struct RigidPose {
  Eigen::Vector3d x = Eigen::Vector3d::Zero(); // m, centre of mass
  // body frame -> world, unit; unaligned because an aligned quaternion pads every kept pose
  // (four per CandidateCache entry, read for every neighbour pair every step) to 96 bytes
  Eigen::Quaternion<double, Eigen::DontAlign> q = Eigen::Quaterniond::Identity();
  double radius = 0.0; // m, farthest vertex from x
  // Which body-frame triangles they are (the shape's SoA): a pose compares only with a pose of
  // the same shape (a tag the host reuses for another particle starts afresh).
  const void *frame = nullptr;
};

// Whether two poses place the same body-frame vertices, so that a motion bound applies. A pose
// without a radius bounds nothing (a body whose host did not describe it).
inline bool same_frame(const RigidPose &then, const RigidPose &now) {
  return now.radius > 0.0 && now.radius == then.radius && now.frame == then.frame;
}

// The rotation's part of the bound: 2 sin(theta / 2) r, theta the angle turned from `then` to
// `now` (|vec| of the unit turn quaternion is sin(theta / 2)).
inline double turn_bound(const RigidPose &then, const RigidPose &now) {
  const Eigen::Quaterniond turn = now.q * then.q.conjugate();
  return 2.0 * turn.vec().norm() * now.radius;
}

// A bound D on how far any vertex of a particle moved from pose `then` to `now` (m):
// |x - x0| + 2 sin(theta / 2) r, exact for the farthest vertex turning about an axis through x;
// infinity when the poses do not describe the same body frame.
double rigid_motion_bound(const RigidPose &then, const RigidPose &now);

// b's pose seen from a: its centre in a's body frame and its turn relative to a.
struct RelativePose {
  Eigen::Vector3d t;
  Eigen::Quaterniond r;
};
RelativePose relative_pose(const RigidPose &a, const RigidPose &b);

// A bound on how far the two bodies' vertices moved relative to each other from relative pose
// `then` to `now` (m): b's vertices seen from a's frame, |t - t0| + 2 sin(theta / 2) r_b, or
// a's seen from b's, whichever is smaller. The distance between a point of a and a point of b
// changes by at most either, and unlike the sum of both bodies' own motions it stays small
// while the two move together (a flowing bed, a pile carried on a belt). A body of radius 0
// (a wall, whose frame is the world's) gives no bound of its own; infinity if neither does.
double relative_motion_bound(const RelativePose &then, const RelativePose &now, double radius_a,
                             double radius_b);

} // namespace tri
