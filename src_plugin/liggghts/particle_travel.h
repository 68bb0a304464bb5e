// Per owned particle, a running sum of how far its vertices can have moved (tri::Travel,
// candidate_cache.h: the travel proof), kept by pair tri/gran so that a neighbour pair proven
// apart stays proven, from two sums and its kept gap, while the pairs are listed.
//
// The sums live in one epoch: they are indexed by local atom, so whenever LIGGGHTS may have
// renumbered, sorted, exchanged, inserted or deleted atoms (a neighbour-list rebuild, the setup
// of a run) they restart from zero under a new epoch, and every gap kept in an older one no
// longer counts. Epochs are unique in the process (two pair styles, or a style replaced by
// another, never share one). Ghost atoms have no sum: their pairs take the other proofs.
#pragma once

#include "candidate_cache.h"

#include <vector>

namespace LAMMPS_NS {
class Atom;
class FixTriParticles;
} // namespace LAMMPS_NS

namespace tri_liggghts {

class ParticleTravel {
public:
  // Once per force evaluation, before the pairs are listed: each owned particle's sum grows by
  // the bound of its motion since the last call (rigid_motion_bound), or all restart when
  // `renumbered` (or the number of owned atoms changed).
  void update(const LAMMPS_NS::FixTriParticles &particles, const LAMMPS_NS::Atom *atom,
              bool renumbered);
  // The sums of atoms i and j in this epoch; epoch 0 unless both are owned.
  tri::Travel of(int i, int j) const {
    if (i < 0 || j < 0 || i >= atoms_ || j >= atoms_)
      return {};
    return {sum_[i], sum_[j], epoch_};
  }
  std::size_t bytes() const {
    return sum_.capacity() * sizeof(double) + last_.capacity() * sizeof(tri::RigidPose) +
           tags_.capacity() * sizeof(long long);
  }

private:
  std::vector<double> sum_;          // m, per owned atom
  std::vector<tri::RigidPose> last_; // per owned atom: its pose at the last update
  std::vector<long long> tags_;      // per owned atom: its tag in this epoch
  int atoms_ = 0;                    // owned atoms of this epoch
  long long epoch_ = 0;
};

} // namespace tri_liggghts
