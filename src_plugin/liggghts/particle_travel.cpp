#include "particle_travel.h"

#include "fix_tri_particles.h"

#include "atom.h"

#include <atomic>
#include <limits>

namespace tri_liggghts {

namespace {
std::atomic<long long> last_epoch{0};
}

void ParticleTravel::update(const LAMMPS_NS::FixTriParticles &particles,
                            const LAMMPS_NS::Atom *atom, bool renumbered) {
  const int n = atom->nlocal;
  bool restart = renumbered || epoch_ == 0 || n != atoms_;
  // An atom in another slot (a command that migrated atoms without a rebuild, `run pre no`
  // after it) restarts the epoch as well: the sums are the slots'.
  for (int i = 0; i < n && !restart; ++i)
    restart = atom->tag[i] != tags_[i];
  if (restart) {
    epoch_ = ++last_epoch;
    atoms_ = n;
    sum_.assign(n, 0.0);
    last_.resize(n);
    tags_.assign(atom->tag, atom->tag + n);
  }
  double *const *x = atom->x;
  for (int i = 0; i < n; ++i) {
    tri::RigidPose now;
    const int s = particles.shape_index(i);
    if (s >= 0) { // an atom not yet given its shape (inserted this step) has no bound
      now.x = Eigen::Vector3d(x[i][0], x[i][1], x[i][2]);
      now.q = particles.orientation(i);
      now.radius = particles.shape(s).bounding_radius;
      now.frame = &particles.shape(s).soa;
    }
    if (!restart)
      sum_[i] += rigid_motion_bound(last_[i], now); // infinity: never proven again this epoch
    last_[i] = now;
  }
}

} // namespace tri_liggghts
