// fix tri/adapt_dt: the paper's adaptive time step. After every force evaluation: if some
// contact's closest triangle distance is below `fraction` x epsilon (default 0.2, the paper's
// rule), dt is halved; if there is no contact at all, dt grows by `growth` (default 10%);
// otherwise it stays. dt stays within [dtmin, dtmax]; every change is written to the log.
// epsilon is the particles' soft-layer width (fix tri/particles).
//
//   fix ID all tri/adapt_dt dtmax DT dtmin DT [fraction F] [growth G]
#pragma once

#include "fix.h"

namespace LAMMPS_NS {

class FixTriAdaptDt : public Fix {
public:
  FixTriAdaptDt(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void end_of_step() override;
  double compute_vector(int) override;

private:
  class FixTriParticles *particles_ = nullptr;
  double dtmax_ = 0.0, dtmin_ = 0.0, fraction_ = 0.2, growth_ = 1.1;
  long long halvings_ = 0, growths_ = 0;
  void set_dt(double dt, const char *why);
};

} // namespace LAMMPS_NS
