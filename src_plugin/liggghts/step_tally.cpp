#include "step_tally.h"

#include "fix_tri_wall.h"
#include "pair_tri_gran.h"

#include "force.h"
#include "lammps.h"
#include "modify.h"

#include <mpi.h>

#include <cstring>
#include <vector>

namespace tri_liggghts {

GlobalTally global_tally(LAMMPS_NS::LAMMPS *lmp, TallySource source) {
  GlobalTally g;
  tri::InteractionTally local;
  if (auto *pair = dynamic_cast<LAMMPS_NS::PairTriGran *>(lmp->force->pair)) {
    if (source != TallySource::wall)
      local += pair->tally();
    g.have_pair = true;
  }
  for (int i = 0; i < lmp->modify->nfix; ++i)
    if (std::strcmp(lmp->modify->fix[i]->style, "tri/wall") == 0) {
      if (source != TallySource::pair)
        local += static_cast<LAMMPS_NS::FixTriWall *>(lmp->modify->fix[i])->tally();
      ++g.walls;
    }

  const tri::ContactStats &d = local.distance;
  std::vector<long long> counts = {local.body_pairs_checked, local.body_pairs_in_contact,
                                   local.contacts_before,    local.contacts_after,
                                   local.penetrations,       d.triangle_pairs_tested,
                                   d.triangle_pairs_culled,  d.contacts,
                                   d.penalty_pairs,          d.fallbacks};
  const int nhist = tri::kMaxPenaltyIterations + 1;
  counts.insert(counts.end(), d.newton_histogram, d.newton_histogram + nhist);
  std::vector<long long> sums(counts.size());
  MPI_Allreduce(counts.data(), sums.data(), static_cast<int>(counts.size()), MPI_LONG_LONG,
                MPI_SUM, lmp->world);
  double extremes[2] = {local.max_overlap, -local.min_distance}, global_extremes[2];
  MPI_Allreduce(extremes, global_extremes, 2, MPI_DOUBLE, MPI_MAX, lmp->world);

  tri::InteractionTally &t = g.all;
  t.body_pairs_checked = sums[0];
  t.body_pairs_in_contact = sums[1];
  t.contacts_before = sums[2];
  t.contacts_after = sums[3];
  t.penetrations = sums[4];
  t.distance.triangle_pairs_tested = sums[5];
  t.distance.triangle_pairs_culled = sums[6];
  t.distance.contacts = sums[7];
  t.distance.penalty_pairs = sums[8];
  t.distance.fallbacks = sums[9];
  for (int k = 0; k < nhist; ++k)
    t.distance.newton_histogram[k] = sums[10 + k];
  t.max_overlap = global_extremes[0];
  t.min_distance = -global_extremes[1];
  return g;
}

} // namespace tri_liggghts
