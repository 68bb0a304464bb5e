// The rigid velocity field v(p) = v + omega x (p - centre) of a moving wall patch, from the
// velocities of its nodes (LIGGGHTS's fix move/mesh moves meshes rigidly: linear, rotate,
// wiggle, riggle, viblin, vibrot, and their sums). With it a wall is a rigid body of infinite
// mass whose velocity at the contact point is exact, however far the point is from the nodes,
// instead of a mean node velocity that misses omega x (p - mean) on a rotating drum.
//
// Least squares: centre = the nodes' mean, v = their mean velocity, omega minimises
// sum_k |v + omega x r_k - v_k|^2 (r_k = p_k - centre), i.e. M omega = sum_k r_k x (v_k - v)
// with M = sum_k (|r_k|^2 I - r_k r_k^T). Exact (to rounding) for node velocities of a rigid
// motion whenever the nodes are not all on one line (any triangle). For collinear nodes M is
// singular and the spin about that line is undetermined: the minimum-norm omega is taken (it
// is exact for every point on the line). Non-rigid node velocities (a deforming mesh) give the
// best rigid fit. n == 0: everything zero.
#pragma once

#include <Eigen/Core>

namespace tri {

struct RigidMotion {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(); // m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero(); // m/s, at the centre
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();    // rad/s
};

RigidMotion fit_rigid_motion(const Eigen::Vector3d *points, const Eigen::Vector3d *velocities,
                             int n);

} // namespace tri
