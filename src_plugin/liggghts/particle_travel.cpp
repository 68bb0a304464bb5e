#include "particle_travel.h"

#include "fix_tri_particles.h"

#include "atom.h"

#include <algorithm>
#include <atomic>

namespace tri_liggghts {

namespace {
std::atomic<long long> last_epoch{0};
}

void ParticleTravel::begin_step(const LAMMPS_NS::Atom *atom, bool renumbered) {
  ++step_;
  const int n = atom->nlocal;
  // An atom in another slot (a command that migrated atoms without a rebuild, `run pre no`
  // after it) begins a new epoch as well: the sums are the slots'.
  if (!renumbered && epoch_ != 0 && n == atoms_ && std::equal(tags_.begin(), tags_.end(), atom->tag))
    return;
  epoch_ = ++last_epoch;
  atoms_ = n;
  tags_.assign(atom->tag, atom->tag + n);
  sum_.resize(n);
  last_.resize(n);
  since_.assign(n, 0);
  step_of_.assign(n, 0);
}

void ParticleTravel::touch(const LAMMPS_NS::FixTriParticles &particles, const LAMMPS_NS::Atom *atom,
                           int i) {
  if (i >= atoms_ || step_of_[i] == step_)
    return;
  step_of_[i] = step_;
  tri::RigidPose now;
  const int s = particles.shape_index(i);
  if (s >= 0) { // an atom not yet given its shape (inserted this step) has no bound
    now.x = Eigen::Vector3d(atom->x[i][0], atom->x[i][1], atom->x[i][2]);
    now.q = particles.orientation(i);
    now.radius = particles.shape(s).bounding_radius;
    now.frame = &particles.shape(s).soa;
  }
  if (since_[i] == epoch_) {
    sum_[i] += tri::rigid_motion_bound(last_[i], now); // infinity: not proven again this epoch
  } else {
    since_[i] = epoch_;
    sum_[i] = 0.0;
  }
  last_[i] = now;
}

} // namespace tri_liggghts
