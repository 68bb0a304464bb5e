// compute tri/contact/atom: per particle, the number of bodies it touches at the last force
// evaluation (other particles through pair tri/gran, wall meshes through fix tri/wall: a mesh
// counts once however many contact points), as LIGGGHTS's compute contact/atom counts the
// contacts of spheres.
//
//   compute ID group tri/contact/atom [pair] [wall]
// pair, wall: which contacts count (default both). Atoms outside the group get 0. A run with
// this compute records the contacts at every step (without it, nothing is recorded).
#pragma once

#include "compute.h"

#include "contact_board.h"

namespace LAMMPS_NS {

class ComputeTriContactAtom : public Compute {
public:
  ComputeTriContactAtom(class LAMMPS *, int &iarg, int narg, char **arg);
  ~ComputeTriContactAtom() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

private:
  tri_liggghts::TallySource source_ = tri_liggghts::TallySource::all;
  class FixTriParticles *particles_ = nullptr;
  int nmax_ = 0;
  double *count_ = nullptr;
};

} // namespace LAMMPS_NS
