#include "fix_tri_nve.h"

#include "fix_tri_particles.h"

#include "rigid_body.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixTriNVE::FixTriNVE(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {
  if (narg > 3) {
    const std::string msg = std::string("Fix tri/nve: unknown keyword '") + arg[3] + "'";
    error->all(FLERR, msg.c_str());
  }
  time_integrate = 1;
}

int FixTriNVE::setmask() { return INITIAL_INTEGRATE | FINAL_INTEGRATE; }

void FixTriNVE::init() {
  particles_ = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0));
  if (!particles_)
    error->all(FLERR, "Fix tri/nve requires fix tri/particles (define it before the run)");
  reset_dt();
}

void FixTriNVE::reset_dt() {
  dtv_ = update->dt;
  dtf_ = 0.5 * update->dt * force->ftm2v;
}

// omega is authoritative only where it no longer matches the angular momentum exactly, i.e.
// where the user changed it (`set ... omega`, a data file). A restarted run finds omega and
// L consistent to the bit, so its trajectory is not perturbed by this.
void FixTriNVE::setup(int) {
  double **omega = atom->omega;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit))
      continue;
    const Eigen::Quaterniond q = particles_->orientation(i);
    const Eigen::Vector3d inertia = particles_->principal_inertia(i);
    const Eigen::Vector3d w_now(omega[i][0], omega[i][1], omega[i][2]);
    if (tri::angular_velocity_unit(q, particles_->angular_momentum(i), inertia.cwiseInverse()) ==
        w_now) // what sync_omega wrote
      continue;
    particles_->set_angular_momentum(i, tri::angmom_from_omega(q, w_now, inertia));
    sync_omega(i);
  }
}

void FixTriNVE::kick_rotation(int i, double dt) {
  const double *t = atom->torque[i];
  particles_->set_angular_momentum(i, particles_->angular_momentum(i) +
                                          dt * Eigen::Vector3d(t[0], t[1], t[2]));
}

void FixTriNVE::sync_omega(int i) {
  const Eigen::Vector3d w =
      tri::angular_velocity_unit(particles_->orientation(i), particles_->angular_momentum(i),
                                 particles_->principal_inertia(i).cwiseInverse());
  for (int k = 0; k < 3; ++k)
    atom->omega[i][k] = w[k];
}

void FixTriNVE::initial_integrate(int) {
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit))
      continue;
    // Right after read_restart: the forces of the step the file was written at.
    particles_->take_restored_force_and_torque(i, f[i], atom->torque[i]);
    const double dtfm = dtf_ / rmass[i];
    for (int k = 0; k < 3; ++k) {
      v[i][k] += dtfm * f[i][k];
      x[i][k] += dtv_ * v[i][k];
    }
    // kick_rotation, rotate_free and sync_omega in one pass over the atom's state.
    const double *t = atom->torque[i];
    Eigen::Vector3d L = particles_->angular_momentum(i) + dtf_ * Eigen::Vector3d(t[0], t[1], t[2]);
    Eigen::Quaterniond q = particles_->orientation(i);
    const Eigen::Vector3d inertia = particles_->principal_inertia(i);
    tri::rotate_free(q, L, inertia, dtv_);
    particles_->set_orientation(i, q);
    particles_->set_angular_momentum(i, L);
    const Eigen::Vector3d w = tri::angular_velocity_unit(q, L, inertia.cwiseInverse());
    for (int k = 0; k < 3; ++k)
      atom->omega[i][k] = w[k];
  }
}

void FixTriNVE::final_integrate() {
  double **v = atom->v, **f = atom->f;
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit))
      continue;
    const double dtfm = dtf_ / rmass[i];
    for (int k = 0; k < 3; ++k)
      v[i][k] += dtfm * f[i][k];
    kick_rotation(i, dtf_);
    sync_omega(i);
  }
}
