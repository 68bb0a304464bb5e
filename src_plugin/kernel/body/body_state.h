// The motion of a rigid body at the start of a step's force computation, as the contact force
// law reads it: the velocity of the body's material at a point p is v + omega x (p - x).
#pragma once

#include <Eigen/Core>

namespace tri {

// A particle: its centre of mass, velocity and spin, and its mass. A wall (a mesh moved by
// LIGGGHTS's fix move/mesh, body/rigid_motion.h) is a body of infinite mass: mass <= 0, x the
// centre of its fitted rigid motion, v the velocity there and omega its spin (zero for a wall
// at rest or in translation).
struct BodyState {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();     // m, centre of mass (a wall: of its motion)
  Eigen::Vector3d v = Eigen::Vector3d::Zero();     // m/s
  Eigen::Vector3d omega = Eigen::Vector3d::Zero(); // rad/s, world frame
  double mass = 0.0;                               // kg; <= 0 for a wall
};

} // namespace tri
