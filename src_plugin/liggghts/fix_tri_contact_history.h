// LIGGGHTS's fix contacthistory (created by every PairGran that keeps history) looks for its
// pair style by the exact name "gran" in init() and crashes on a null pointer when the pair
// is called anything else. This subclass, registered under the same style name, behaves
// exactly as LIGGGHTS's for pair_style gran and accepts tri/gran as its pair otherwise; it
// stores, migrates and restarts the history with LIGGGHTS's own code.
#pragma once

#include "fix_contact_history.h"

namespace LAMMPS_NS {

class FixTriContactHistory : public FixContactHistory {
public:
  FixTriContactHistory(class LAMMPS *lmp, int narg, char **arg) : FixContactHistory(lmp, narg, arg) {}
  void init() override;
};

} // namespace LAMMPS_NS
