// compute tri/stats: contact statistics of the last force evaluation (every source on the
// contact board: pair tri/gran and all fix tri/wall), summed over ranks, as a global vector for
// thermo_style (c_ID[k]). The columns, their names, units and meanings are the statistics
// table's (interaction_tally.h; `tri-stats-columns` prints it,
// src_plugin/doc/compute_tri_stats.md shows it).
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
  class FixTriParticles *particles_ = nullptr;
  tri_liggghts::TallySource source_ = tri_liggghts::TallySource::all;
};

} // namespace LAMMPS_NS
