#include "body/rigid_pose.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tri {

double rigid_motion_bound(const RigidPose &then, const RigidPose &now) {
  if (!same_frame(then, now))
    return std::numeric_limits<double>::infinity();
  return (now.x - then.x).norm() + turn_bound(then, now);
}

RelativePose relative_pose(const RigidPose &a, const RigidPose &b) {
  const Eigen::Quaterniond qa(a.q), qb(b.q);
  return {qa.conjugate() * (b.x - a.x), qa.conjugate() * qb};
}

double relative_motion_bound(const RelativePose &then, const RelativePose &now, double radius_a,
                             double radius_b) {
  constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  const Eigen::Quaterniond turn = now.r * then.r.conjugate();
  const double chord = 2.0 * turn.vec().norm(); // 2 sin(theta / 2)
  double d = kUnbounded;
  if (radius_b > 0.0)
    d = (now.t - then.t).norm() + chord * radius_b;
  if (radius_a > 0.0) { // a's centre in b's frame: -r^-1 t
    const Eigen::Vector3d a_now = -(now.r.conjugate() * now.t),
                          a_then = -(then.r.conjugate() * then.t);
    d = std::min(d, (a_now - a_then).norm() + chord * radius_a);
  }
  return std::isfinite(d) ? d : kUnbounded;
}

} // namespace tri
