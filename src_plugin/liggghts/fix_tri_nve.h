// fix tri/nve: velocity-Verlet translation and a symplectic rigid-body rotation (NO_SQUISH,
// full inertia tensor, tri::rotate_free) for the particles of fix tri/particles. It keeps
// LIGGGHTS's omega equal to the angular velocity implied by orientation and angular
// momentum, so computes, dumps and contact styles see the spin. Forces and torques from any
// fix (gravity, addforce, walls) and pair style enter through f and torque.
#pragma once

#include "fix.h"

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
};

} // namespace LAMMPS_NS
