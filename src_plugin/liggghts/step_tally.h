// The contact statistics of the last force evaluation over every source on the contact board
// (contact_board.h), summed over all ranks column by column as the statistics table says
// (interaction_tally.h: counts summed, deepest overlap maxed, closest distance minimised).
// Read by compute tri/stats, fix tri/adapt_dt and the run-safety checks.
#pragma once

#include "contact_board.h"

#include <mpi.h>

namespace tri_liggghts {

tri::InteractionTally global_tally(const ContactBoard &board, MPI_Comm world,
                                   TallySource source = TallySource::all);

} // namespace tri_liggghts
