// fix tri/nve: velocity-Verlet translation and a symplectic rigid-body rotation (NO_SQUISH,
// full inertia tensor, tri::rotate_free) for the particles of fix tri/particles. It keeps
// LIGGGHTS's omega equal to the angular velocity implied by orientation and angular
// momentum, so computes, dumps and contact styles see the spin. Forces and torques from any
// fix (gravity, addforce, walls) and pair style enter through f and torque.
#pragma once

#include "fix.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace LAMMPS_NS {

class FixTriNVE : public Fix {
public:
  FixTriNVE(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void reset_dt() override;

private:
  class FixTriParticles *particles_ = nullptr;
  double dtv_ = 0.0, dtf_ = 0.0;
  void kick_rotation(int i, double dt);
  void sync_omega(int i); // omega := angular velocity implied by q and L
  // The group's atoms of one initial_integrate in the structure-of-arrays form of
  // tri::rotate_free_many (kept between steps: no allocation once grown).
  struct RotorBatch {
    std::vector<double> qw, qx, qy, qz, lx, ly, lz, i0, i1, i2, wx, wy, wz;
    std::vector<int> atom, large;
    void resize(int n);
    void set(int k, int i, const Eigen::Quaterniond &q, const Eigen::Vector3d &l,
             const Eigen::Vector3d &inertia);
  };
  RotorBatch rotor_;
};

} // namespace LAMMPS_NS
