#include "step_tally.h"

#include <vector>

namespace tri_liggghts {

tri::InteractionTally global_tally(const ContactBoard &board, MPI_Comm world, TallySource source) {
  const tri::InteractionTally local = board.local(source);
  const std::vector<tri::StatColumn> &columns = tri::stats_columns();
  // One reduction per kind; counts travel as doubles (exact below 2^53).
  std::vector<double> values[3], reduced[3];
  const MPI_Op ops[3] = {MPI_SUM, MPI_MAX, MPI_MIN};
  for (const tri::StatColumn &c : columns)
    values[static_cast<int>(c.reduction)].push_back(c.value(local));
  for (int r = 0; r < 3; ++r) {
    reduced[r].resize(values[r].size());
    if (!values[r].empty())
      MPI_Allreduce(values[r].data(), reduced[r].data(), static_cast<int>(values[r].size()),
                    MPI_DOUBLE, ops[r], world);
  }
  tri::InteractionTally global;
  std::size_t next[3] = {0, 0, 0};
  for (const tri::StatColumn &c : columns) {
    const int r = static_cast<int>(c.reduction);
    c.assign(global, reduced[r][next[r]++]);
  }
  return global;
}

} // namespace tri_liggghts
