#include "compute_tri_erotate.h"

#include "fix_tri_particles.h"

#include "body/rigid_body.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "update.h"

#include <mpi.h>

#include <string>

using namespace LAMMPS_NS;

ComputeTriERotate::ComputeTriERotate(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg) {
  if (iarg < narg) {
    const std::string msg = std::string("Compute tri/erotate: unknown keyword '") + arg[iarg] + "'";
    error->all(FLERR, msg.c_str());
  }
  scalar_flag = 1;
  extscalar = 1;
}

void ComputeTriERotate::init() {
  particles_ = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0));
  if (!particles_)
    error->all(FLERR, "Compute tri/erotate requires fix tri/particles (define it before the run)");
}

double ComputeTriERotate::compute_scalar() {
  invoked_scalar = update->ntimestep;
  const int *mask = atom->mask;
  double local = 0.0;
  // From L and the orientation rather than LIGGGHTS's omega, so the value does not depend on
  // fix tri/nve having synchronised omega since the last change of L.
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit))
      continue;
    const Eigen::Vector3d L = particles_->angular_momentum(i);
    const Eigen::Vector3d w =
        tri::angular_velocity(particles_->orientation(i), L, particles_->principal_inertia(i));
    local += L.dot(w);
  }
  MPI_Allreduce(&local, &scalar, 1, MPI_DOUBLE, MPI_SUM, world);
  scalar *= 0.5 * force->mvv2e;
  return scalar;
}
