// Per owned particle, a running sum of how far its vertices can have moved (tri::Travel,
// candidate_cache.h: the travel proof), kept by pair tri/gran so that a neighbour pair proven
// apart stays proven, from two sums and its kept gap, while the pairs are listed.
//
// A sum grows only when its particle is asked for (touch: at most once a step), by the bound
// of its motion since it was last asked (rigid_motion_bound, from that pose to the current one:
// a bound over several steps at once, no looser than their sum), so a particle without a
// neighbour within reach (free flight) costs nothing.
//
// The sums live in one epoch: they are indexed by local atom, so whenever LIGGGHTS may have
// renumbered, sorted, exchanged, inserted or deleted atoms (a neighbour-list rebuild, the setup
// of a run, a slot holding another tag) a new epoch begins, in which each particle starts from
// zero when first asked, and every gap kept in an older one no longer counts. Epochs are unique
// in the process (two pair styles, or a style replaced by another, never share one). Ghost atoms
// have no sum: their pairs take the other proofs.
#pragma once

#include "distance/candidate_cache.h"

#include <cstddef>
#include <vector>

namespace LAMMPS_NS {
class Atom;
class FixTriParticles;
} // namespace LAMMPS_NS

namespace tri_liggghts {

class ParticleTravel {
public:
  // Once per force evaluation, before the pairs are listed: a new epoch when `renumbered` (or
  // when the owned atoms' count or tags changed).
  void begin_step(const LAMMPS_NS::Atom *atom, bool renumbered);
  // Brings owned atom i's sum up to its current pose (first call this step). Callable from the
  // host's listing threads: the first to ask for an atom brings it up, one that asks meanwhile
  // waits for it (the sum is the same whichever thread computes it). Ghost atoms are ignored.
  void touch(const LAMMPS_NS::FixTriParticles &particles, const LAMMPS_NS::Atom *atom, int i);
  // The sums of atoms i and j, both touched this step (a sum from an earlier step would bound
  // the motion since then, not since now); epoch 0 otherwise (a ghost). Read-only: callable from
  // the evaluation's threads.
  tri::Travel of(int i, int j) const {
    if (i < 0 || j < 0 || i >= atoms_ || j >= atoms_ || step_of_[i] != step_ ||
        step_of_[j] != step_)
      return {};
    return {sum_[i], sum_[j], epoch_};
  }
  std::size_t bytes() const {
    return sum_.capacity() * sizeof(double) + last_.capacity() * sizeof(tri::RigidPose) +
           (tags_.capacity() + since_.capacity() + step_of_.capacity()) * sizeof(long long);
  }

private:
  std::vector<double> sum_;          // m, per owned atom
  std::vector<tri::RigidPose> last_; // per owned atom: its pose when last touched
  std::vector<long long> tags_;      // per owned atom: its tag in this epoch
  std::vector<long long> since_;     // per owned atom: the epoch of its sum (touched in it)
  // Per owned atom: the step it was last touched; minus this step while a thread touches it
  // (claimed and read atomically in touch).
  std::vector<long long> step_of_;
  int atoms_ = 0;                    // owned atoms of this epoch
  long long epoch_ = 0, step_ = 0;
};

} // namespace tri_liggghts
