// compute tri/contact/local: one row per contact point of the last force evaluation (pair
// tri/gran, every fix tri/wall), for `dump local`: the contact network, as LIGGGHTS's compute
// pair/gran/local and wall/gran/local give it for spheres.
//
//   compute ID group tri/contact/local [pair] [wall] [value keywords]
// pair, wall: which contacts (default both). Value keywords, in this column order whatever
// order they are given in (default: all of them):
//   pos (6)              x of particle i, then x of particle j (a wall: the contact point)
//   vel (6)              v of i, then v of j (a wall: the wall's velocity at the contact point)
//   id (3)               pair: tag i, tag j, 1 across a periodic boundary else 0;
//                        wall: tag i, -(k+1) for the k-th mesh of its fix tri/wall (from 0),
//                        the global id of the wall triangle deepest in the contact
//   force (3)            the contact's force on i, N
//   force_normal (3)     its part along the contact normal
//   force_tangential (3) its friction part
//   torque (3)           its torque on i about i's centre, N m (friction couples included; not
//                        divided by a radius as pair/gran/local's)
//   contactArea (1)      the face patch's area, m^2; 0 for a point-like contact
//   delta (1)            the overlap of the soft layers, m
//   contactPoint (3)     where the contact's force acts, m
//   normal (3)           unit, from i towards j (the wall)
//   kind (1)             1 face, 2 edge, 3 vertex, 4 deep (tri::ContactKind)
// Particle i of a pair is the one with the lower tag. A pair is listed once over all ranks: on
// the rank that owns i. Rows of a pair whose atoms are not both in the group are left out (a
// wall's: whose particle is not). The data are those of the step's force evaluation; a run
// with this compute records them at every step (without it, nothing is recorded).
#pragma once

#include "compute.h"

#include "contact_board.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeTriContactLocal : public Compute {
public:
  ComputeTriContactLocal(class LAMMPS *, int &iarg, int narg, char **arg);
  ~ComputeTriContactLocal() override;
  void init() override;
  void compute_local() override;
  double memory_usage() override;

private:
  enum Value { pos, vel, id, force, force_normal, force_tangential, torque, contact_area, delta,
               contact_point, normal, kind, num_values };
  bool value_[num_values] = {};
  int columns_ = 0;
  tri_liggghts::TallySource source_ = tri_liggghts::TallySource::all;
  class FixTriParticles *particles_ = nullptr;
  int max_rows_ = 0;
  std::vector<const tri_liggghts::PublishedContact *> rows_;

  bool wanted(const tri_liggghts::PublishedContact &c) const;
  void grow(int rows);
  void fill_row(const tri_liggghts::PublishedContact &c, double *out) const;
};

} // namespace LAMMPS_NS
