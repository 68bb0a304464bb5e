#include "fix_tri_nve.h"

#include "fix_tri_particles.h"

#include "body/rigid_body.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "update.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

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
  // LIGGGHTS takes any `timestep`; a step that is not a positive number turns every contact
  // into a source of energy and moves the particles backwards out of the box.
  if (!(update->dt > 0.0) || !std::isfinite(update->dt)) {
    char msg[160];
    std::snprintf(msg, sizeof msg, "Fix tri/nve: the time step must be a positive number, got %g s "
                                   "(the timestep command)", update->dt);
    error->all(FLERR, msg);
  }
  reset_dt();
}

void FixTriNVE::reset_dt() {
  dtv_ = update->dt;
  dtf_ = 0.5 * update->dt * force->ftm2v;
  // dtfm depends on dtf; the shapes are known by now (init comes first)
  mass_cache_.assign(static_cast<std::size_t>(std::max(omp_get_max_threads(), 1)),
                     std::vector<MassProperties>(particles_ ? particles_->num_shapes() : 0));
}

int FixTriNVE::integration_threads(int n) {
  const int threads = omp_get_max_threads();
  if (threads <= 1 || n < kAtomsPerThread * threads)
    return 1;
  if (mass_cache_.size() < static_cast<std::size_t>(threads)) // threads added since init
    mass_cache_.resize(static_cast<std::size_t>(threads), mass_cache_.front());
  return threads;
}

// Inline: twice per atom and step, a hit but for the first atom of each shape.
inline __attribute__((always_inline)) const FixTriNVE::MassProperties &
FixTriNVE::mass_properties(int i, double rmass, std::vector<MassProperties> &cache) {
  MassProperties &m = cache[particles_->shape_index(i)];
  if (!(m.rmass == rmass))
    compute_mass_properties(i, m);
  return m;
}

void FixTriNVE::compute_mass_properties(int i, MassProperties &m) {
  m.rmass = atom->rmass[i];
  m.dtfm = dtf_ / m.rmass;
  const Eigen::Vector3d inertia = particles_->principal_inertia(i);
  for (int k = 0; k < 3; ++k)
    m.inverse[k] = 1.0 / inertia[k];
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
  double *l = particles_->angular_momentum_data(i);
  for (int k = 0; k < 3; ++k)
    l[k] += dt * t[k];
}

void FixTriNVE::sync_omega(int i) {
  const Eigen::Vector3d w =
      tri::angular_velocity_unit(particles_->orientation(i), particles_->angular_momentum(i),
                                 particles_->principal_inertia(i).cwiseInverse());
  for (int k = 0; k < 3; ++k)
    atom->omega[i][k] = w[k];
}

void FixTriNVE::initial_integrate(int) {
  // Right after read_restart: the forces of the step the file was written at.
  particles_->take_restored_forces_and_torques(groupbit);
  rotor_.resize(atom->nlocal);
  over_shares(&FixTriNVE::initial_integrate_share);
}

// share(first, last, cache) over the owned atoms, on integration_threads' threads, each a
// contiguous share with its own cache.
void FixTriNVE::over_shares(void (FixTriNVE::*share)(int, int, std::vector<MassProperties> &)) {
  const int nlocal = atom->nlocal;
  const int threads = integration_threads(nlocal);
  if (threads == 1) {
    (this->*share)(0, nlocal, mass_cache_[0]);
    return;
  }
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    (this->*share)(static_cast<int>(static_cast<long>(nlocal) * t / threads),
                   static_cast<int>(static_cast<long>(nlocal) * (t + 1) / threads),
                   mass_cache_[static_cast<std::size_t>(t)]);
  }
}

// Atoms [first, last), in the rotor batch's columns from `first` on.
void FixTriNVE::initial_integrate_share(int first, int last, std::vector<MassProperties> &cache) {
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  // Translation and the first rotational kick per atom; the free rotation of all atoms at
  // once (tri::rotate_free_many, vectorised across atoms: one atom's rotor is a long serial
  // chain, most of a free-flight step when done one atom at a time). Each atom's bits are
  // rotate_free's whatever its place in the batch, so thread and rank counts change nothing.
  using Batch = RotorBatch;
  double *const b = rotor_.data.data() + first; // column c, atom k: b[c * stride + k]
  const std::size_t stride = rotor_.stride;
  int *const batch_atom = rotor_.atom.data() + first;
  int n = 0;
  for (int i = first; i < last; ++i) {
    if (!(mask[i] & groupbit))
      continue;
    const MassProperties &m = mass_properties(i, rmass[i], cache);
    for (int k = 0; k < 3; ++k) {
      v[i][k] += m.dtfm * f[i][k];
      x[i][k] += dtv_ * v[i][k];
    }
    kick_rotation(i, dtf_); // L is not changed by the free rotation: final here
    const double *q = particles_->orientation_data(i), *l = particles_->angular_momentum_data(i);
    batch_atom[n] = i;
    for (int c = 0; c < 4; ++c)
      b[(Batch::qw + c) * stride + n] = q[c];
    for (int c = 0; c < 3; ++c) {
      b[(Batch::lx + c) * stride + n] = l[c];
      b[(Batch::v0 + c) * stride + n] = m.inverse[c];
    }
    ++n;
  }
  auto column = [&](Batch::Column c) { return rotor_.column(c) + first; };
  tri::rotate_free_many(n, column(Batch::qw), column(Batch::qx), column(Batch::qy),
                        column(Batch::qz), column(Batch::lx), column(Batch::ly),
                        column(Batch::lz), column(Batch::v0), column(Batch::v1),
                        column(Batch::v2), dtv_, column(Batch::wx), column(Batch::wy),
                        column(Batch::wz), rotor_.large.data() + first);
  double **omega = atom->omega;
  for (int k = 0; k < n; ++k) {
    const int i = batch_atom[k];
    double *q = particles_->orientation_data(i);
    for (int c = 0; c < 4; ++c)
      q[c] = b[(Batch::qw + c) * stride + k];
    for (int c = 0; c < 3; ++c)
      omega[i][c] = b[(Batch::wx + c) * stride + k];
  }
}

void FixTriNVE::RotorBatch::resize(int n) {
  const std::size_t m = static_cast<std::size_t>(n);
  if (stride < m) {
    // Whole cache lines, plus one: columns a power of two apart (512 atoms: 4 KiB) would all
    // fall into the same L1 set, and the batch's 13 columns would evict each other.
    stride = (m + 7) / 8 * 8 + 8;
    data.resize(columns * stride);
    atom.resize(stride); // every array holds `stride` atoms: n <= stride is all a step checks
    large.resize(stride);
  }
}

void FixTriNVE::final_integrate() { over_shares(&FixTriNVE::final_integrate_share); }

void FixTriNVE::final_integrate_share(int first, int last, std::vector<MassProperties> &cache) {
  double **v = atom->v, **f = atom->f, **omega = atom->omega;
  const double *rmass = atom->rmass;
  const int *mask = atom->mask;
  // The second kick and omega from q and L, atom by atom: omega is a few dozen flops once the
  // inverse moments are at hand, less than copying the atom into a batch and back (the bits
  // of tri::angular_velocity_unit and of sync_omega).
  for (int i = first; i < last; ++i) {
    if (!(mask[i] & groupbit))
      continue;
    const MassProperties &m = mass_properties(i, rmass[i], cache);
    for (int k = 0; k < 3; ++k)
      v[i][k] += m.dtfm * f[i][k];
    kick_rotation(i, dtf_);
    tri::rigid_detail::omega_of_unit(particles_->orientation_data(i),
                                     particles_->angular_momentum_data(i), m.inverse, omega[i]);
  }
}
