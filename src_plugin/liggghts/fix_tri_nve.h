// fix tri/nve: velocity-Verlet translation and a symplectic rigid-body rotation (NO_SQUISH,
// full inertia tensor, tri::rotate_free) for the particles of fix tri/particles. It keeps
// LIGGGHTS's omega equal to the angular velocity implied by orientation and angular
// momentum, so computes, dumps and contact styles see the spin. Forces and torques from any
// fix (gravity, addforce, walls) and pair style enter through f and torque.
#pragma once

#include "fix.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <limits>
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
  // What a half step needs of an atom's mass: dtf / rmass and the inverses of the principal
  // moments (FixTriParticles::principal_inertia). They are a function of the shape,
  // rmass and dtf alone, and the atoms of one shape nearly always share one rmass (density *
  // volume), so they are kept per shape for the rmass last seen and reused wherever an atom's
  // rmass equals it (`set mass` atoms get theirs computed by the same expressions): the bits of
  // computing them per atom, without ten divisions per atom and step (dtf / rmass,
  // rmass / volume and 1 / I, in both halves). Every atom integrated has its shape: fix
  // tri/particles gives it in init() or in the pre_force of the step the atom arrives.
  struct MassProperties {
    double rmass = std::numeric_limits<double>::quiet_NaN(); // NaN: equal to no rmass
    double dtfm = 0.0, inverse[3] = {0.0, 0.0, 0.0};
  };
  // Per thread (the integration's threads each integrate a contiguous share of the atoms), per
  // shape.
  std::vector<std::vector<MassProperties>> mass_cache_;
  // rmass: atom->rmass[i]; cache: the calling thread's.
  const MassProperties &mass_properties(int i, double rmass, std::vector<MassProperties> &cache);
  void compute_mass_properties(int i, MassProperties &m);
  // The threads of a half step over n atoms: each atom's update is its own, so any split
  // gives the same bits; below kAtomsPerThread a thread, the fork costs more than the atoms.
  static constexpr int kAtomsPerThread = 256;
  int integration_threads(int n);
  void initial_integrate_share(int first, int last, std::vector<MassProperties> &cache);
  void final_integrate_share(int first, int last, std::vector<MassProperties> &cache);
  void over_shares(void (FixTriNVE::*share)(int, int, std::vector<MassProperties> &));
  // The group's atoms of one initial_integrate in the structure-of-arrays form of
  // tri::rotate_free_many: one column of `stride` doubles per quantity (kept between steps: no
  // allocation once grown).
  struct RotorBatch {
    enum Column { qw, qx, qy, qz, lx, ly, lz, v0, v1, v2, wx, wy, wz, columns };
    std::vector<double> data;
    std::size_t stride = 0;
    std::vector<int> atom, large;
    void resize(int n);
    double *column(Column c) { return data.data() + c * stride; }
  };
  RotorBatch rotor_;
};

} // namespace LAMMPS_NS
