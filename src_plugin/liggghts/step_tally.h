// The contact statistics of the last force evaluation, over pair tri/gran and every fix
// tri/wall, summed over all ranks (counts summed, deepest overlap maxed, closest distance
// minimised). Read by compute tri/stats and fix tri/adapt_dt.
#pragma once

#include "body_interaction.h"

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tri_liggghts {

struct GlobalTally {
  tri::InteractionTally all;
  bool have_pair = false; // pair tri/gran is defined
  int walls = 0;          // number of fix tri/wall
};

enum class TallySource { all, pair, wall };

GlobalTally global_tally(LAMMPS_NS::LAMMPS *lmp, TallySource source = TallySource::all);

} // namespace tri_liggghts
