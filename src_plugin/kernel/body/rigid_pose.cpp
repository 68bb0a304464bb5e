#include "body/rigid_pose.h"

#include <limits>

namespace tri {

double rigid_motion_bound(const RigidPose &then, const RigidPose &now) {
  if (!same_frame(then, now))
    return std::numeric_limits<double>::infinity();
  return (now.x - then.x).norm() + turn_bound(then, now);
}

} // namespace tri
