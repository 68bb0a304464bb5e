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
  if (i >= atoms_)
    return;
  // GCC's atomic builtins on the plain counter (C++17 has no atomic_ref); outside the listing the
  // counters are read and written plainly.
  long long *stamp = &step_of_[i];
  for (long long seen = __atomic_load_n(stamp, __ATOMIC_ACQUIRE);;) {
    if (seen == step_)
      return;
    if (seen == -step_) { // another thread's, a fraction of a microsecond
      __builtin_ia32_pause();
      seen = __atomic_load_n(stamp, __ATOMIC_ACQUIRE);
      continue;
    }
    if (__atomic_compare_exchange_n(stamp, &seen, -step_, false, __ATOMIC_ACQ_REL,
                                    __ATOMIC_ACQUIRE))
      break;
  }
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
  __atomic_store_n(stamp, step_, __ATOMIC_RELEASE);
}

} // namespace tri_liggghts
