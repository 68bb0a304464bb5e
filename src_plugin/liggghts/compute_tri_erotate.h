// compute tri/erotate: rotational kinetic energy of the triangulated particles of a group,
// summed over ranks, as a global scalar (J in SI units):
//   sum_i 0.5 L_i . omega_i,   omega_i = R_i diag(I_i)^-1 R_i^T L_i
// with the angular momentum L and the orientation R of fix tri/particles and the principal
// moments I of the particle's shape. LIGGGHTS's compute erotate/sphere would take the moment
// of inertia of a sphere of the bounding radius, which is not the particle's.
//
//   compute ID group tri/erotate
#pragma once

#include "compute.h"

namespace LAMMPS_NS {

class ComputeTriERotate : public Compute {
public:
  ComputeTriERotate(class LAMMPS *, int &iarg, int narg, char **arg);
  void init() override;
  double compute_scalar() override;

private:
  class FixTriParticles *particles_ = nullptr;
};

} // namespace LAMMPS_NS
