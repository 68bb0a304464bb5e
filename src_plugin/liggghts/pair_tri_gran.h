// pair_style tri/gran: contact forces between triangulated particles (fix tri/particles).
// LIGGGHTS's granular neighbour list (radius = bounding radius + epsilon) gives candidate
// pairs; for each pair whose bounding spheres overlap, tri::body_interaction finds the
// triangle pairs within the soft layers, reduces them to contact points and applies the
// hooke/stiffness force law with friction; forces and torques go to both particles.
//
//   pair_style tri/gran [contact keywords, see contact_settings.h]
//   pair_coeff * *
//
// Built on LIGGGHTS's PairGran, so the tangential history lives in LIGGGHTS's own contact
// history (fix contacthistory): it survives neighbour-list rebuilds, migration between ranks
// and restarts. Requires newton_pair off, as every granular history pair style.
//
// Determinism: the per-pair work (OpenMP over particle pairs, or inside one pair) writes
// results into a per-pair slot, and one thread sums them afterwards, so the result does not
// depend on the thread count. It does not depend on the number of MPI ranks either: every
// pair is evaluated as (lower atom tag, higher atom tag), whichever atom the rank owns and
// whichever order the neighbour list has them in (tri::body_interaction(b, a) equals
// -body_interaction(a, b) only to rounding), and the contributions to an atom are summed in
// the order of the partners' tags, not the neighbour list's, which follows the decomposition.
// So a pair's force is bitwise the same on every rank that evaluates it, and so is each
// atom's total.
#pragma once

#include "pair_gran.h"

#include "contact_settings.h"
#include "material_table.h"

#include <vector>

namespace LAMMPS_NS {

class PairTriGran : public PairGran {
public:
  explicit PairTriGran(class LAMMPS *);
  void settings(int, char **) override;
  void init_granular() override;
  bool contact_match(const std::string, const std::string) override { return false; }
  int64_t hashcode() override { return 0x7472692f6772616eLL; } // "tri/gran"
  double stressStrainExponent() override { return 1.0; }

  // Statistics of the last force evaluation on this rank.
  const tri::InteractionTally &tally() const { return tally_; }

protected:
  void compute_force(int eflag, int vflag, int addflag) override;

private:
  struct Task {
    int i, j;
    bool swapped;    // evaluated as (j, i): tag[j] < tag[i]
    double *history; // kHistoryDoubles values in LIGGGHTS's contact history, or null
    int *touching;   // LIGGGHTS keeps (migrates, restarts) the history only where this is set
  };
  class FixTriParticles *particles_ = nullptr;
  tri_liggghts::ContactSettings settings_;
  tri_liggghts::MaterialTable materials_;
  std::vector<Task> tasks_;
  std::vector<tri::PairForceResult> results_;
  // One pair's force and torque on one atom, to be summed in partner-tag order.
  struct Contribution {
    int atom;
    tagint partner;
    double force[3], torque[3];
  };
  std::vector<Contribution> contributions_;
  std::vector<tri::InteractionScratch> scratch_;    // one per thread
  std::vector<tri::InteractionTally> thread_tally_; // one per thread
  tri::InteractionTally tally_;

  void interact(long k, int thread, double dt, bool update_history); // tasks_[k]
};

} // namespace LAMMPS_NS
