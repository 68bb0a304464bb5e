// compute tri/stats: contact statistics of the last force evaluation (pair tri/gran and all
// fix tri/wall), summed over ranks, as a global vector for thermo_style (c_ID[k]):
//   1 particle pairs checked (bounding spheres overlap; wall patches included)
//   2 particle pairs in contact
//   3 triangle pairs tested by the distance kernel     4 triangle pairs culled by boxes
//   5 contacts before reduction (triangle pairs)       6 contacts after reduction (points)
//   7 brute-force fallbacks                            8 pairs run through the penalty solve
//   9 penetrations (pairs whose real surfaces intersect)
//  10 deepest soft-layer overlap (m)                  11 smallest contact distance (m; 0 if none)
//  12.. Newton histogram: 12 + k counts pairs whose k-th penalty step was the first below
//       tolerance (k = 0: none was), k = 0..32
//
//   compute ID all tri/stats [all|pair|wall]
// all (default): pair tri/gran and every fix tri/wall; pair: particle-particle only;
// wall: particle-wall only.
#pragma once

#include "compute.h"

#include "step_tally.h"

namespace LAMMPS_NS {

class ComputeTriStats : public Compute {
public:
  ComputeTriStats(class LAMMPS *, int &iarg, int narg, char **arg);
  ~ComputeTriStats() override;
  void init() override;
  void compute_vector() override;

private:
  tri_liggghts::TallySource source_ = tri_liggghts::TallySource::all;
};

} // namespace LAMMPS_NS
