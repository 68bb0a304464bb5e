// The run-safety checks of fix tri/particles, read from the contact board (contact_board.h):
// - on the first step of the first run (not after read_restart), an error if real surfaces
//   intersect: particles created inside each other or inside a wall;
// - on every step, an error if, while there are particle-pair contacts, a pair within reach
//   approached by more than epsilon in the step (or, once a particle-wall contact has
//   intersecting surfaces, a particle moved more than epsilon against its force): the time
//   step is too large for the soft layer, and particles would pass through each other.
// - once a run, a WARNING at the first step whose real surfaces intersect (the soft layer is
//   overrun: tri/stats counts them as penetrations), with the depth and a pair.
// It computes no contact itself: what it needs, the sources published.
#pragma once

#include "contact_board.h"

namespace LAMMPS_NS {
class LAMMPS;
}

namespace tri_liggghts {

class RunSafetyMonitor {
public:
  RunSafetyMonitor(LAMMPS_NS::LAMMPS *lmp, double epsilon) : lmp_(lmp), epsilon_(epsilon) {}
  // A run continued from a restart file: intersections come from the dynamics, not set-up.
  void skip_initial_check() { initial_checked_ = true; }
  // The next run warns again at its first intersection.
  void new_run() { warned_ = false; }
  void set_epsilon(double epsilon) { epsilon_ = epsilon; } // `epsilon auto`, once resolved
  // After the pair forces (post_force of fix tri/particles, before the second half-kick: v is
  // still the velocity that carried the particles into this step's positions).
  void after_pair_forces(const ContactBoard &board);
  // After every contact source has published (end_of_step).
  void end_of_step(const ContactBoard &board);

private:
  LAMMPS_NS::LAMMPS *lmp_;
  double epsilon_;
  bool initial_checked_ = false;
  bool warned_ = false;
  // The pair (tag_j > 0) or particle that moved farthest towards a contact this step.
  struct Unresolved {
    double step = 0.0, speed = 0.0; // m per step, m/s
    long tag_i = 0, tag_j = 0;
  } unresolved_;

  void check_initial_overlaps(const ContactBoard &board);
  void find_unresolved_wall_contact(const ContactBoard &board);
  void report_unresolved_contacts();
  void warn_first_penetration(const ContactBoard &board);
};

} // namespace tri_liggghts
