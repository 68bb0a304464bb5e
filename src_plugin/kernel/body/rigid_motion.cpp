#include "body/rigid_motion.h"

#include <Eigen/Dense>

#include <algorithm>

namespace tri {

RigidMotion fit_rigid_motion(const Eigen::Vector3d *points, const Eigen::Vector3d *velocities,
                             int n) {
  RigidMotion m;
  if (n <= 0)
    return m;
  bool moving = false;
  for (int k = 0; k < n; ++k) {
    m.centre += points[k];
    m.velocity += velocities[k];
    moving = moving || !(velocities[k].array() == 0.0).all();
  }
  m.centre /= n;
  m.velocity /= n;
  if (!moving)
    return m; // a static mesh (most walls, every step): the fit below is M omega = 0
  Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  double spread = 0.0;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d r = points[k] - m.centre;
    moment += r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose();
    rhs += r.cross(velocities[k] - m.velocity);
    spread = std::max(spread, r.squaredNorm());
  }
  if (!(spread > 0.0))
    return m; // one point (or all equal): no rotation can be seen
  // Rank-revealing, with a threshold relative to the patch's size, so collinear nodes give the
  // minimum-norm solution instead of a huge spin from rounding.
  Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix3d> solve;
  solve.setThreshold(1e-12);
  solve.compute(moment);
  m.omega = solve.solve(rhs);
  return m;
}

} // namespace tri
