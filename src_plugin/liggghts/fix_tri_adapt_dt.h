// fix tri/adapt_dt: the paper's adaptive time step. After every force evaluation: if some
// contact's closest triangle distance is below `fraction` x epsilon (default 0.2, the paper's
// rule), dt is halved; if there is no contact at all, dt grows by `growth` (default 10%);
// otherwise it stays. dt stays within [dtmin, dtmax]; every change is written to the log.
// epsilon is the particles' soft-layer width (fix tri/particles).
//
// The paper's rule only reacts: at 100 m/s a pair crosses a 0.1 mm soft layer within one step
// of 1e-6 s, before any contact is seen. So dt is also bounded ahead of the step (`approach`,
// default 0.5): no pair of pair tri/gran's neighbour list may advance more than approach x
// epsilon into the region where its soft layers can touch (approach_speed.h: the gap between
// bounding spheres, the approach speed of the centres plus what rotation adds), and no
// particle may move more than half the neighbour skin (the pairs beyond the skin are not
// listed yet). This bound may cut a growth short or lower dt at once, never below dtmin.
//
//   fix ID all tri/adapt_dt dtmax DT dtmin DT [fraction F] [growth G] [approach A]
//
// f_ID[1] dt, [2] halvings, [3] growths, [4] steps whose dt the approach bound lowered.
#pragma once

#include "fix.h"

#include <string>

namespace LAMMPS_NS {

class FixTriAdaptDt : public Fix {
public:
  FixTriAdaptDt(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  double compute_vector(int) override;

private:
  class FixTriParticles *particles_ = nullptr;
  double dtmax_ = 0.0, dtmin_ = 0.0, fraction_ = 0.2, growth_ = 1.1, approach_ = 0.5;
  long long halvings_ = 0, growths_ = 0, limits_ = 0;
  // The largest dt the approach bound allows now (same on every rank); if below `dt`, `why`
  // says which pair or particle sets it.
  double approach_limit(double dt, std::string &why) const;
  void set_dt(double dt, const char *why);
};

} // namespace LAMMPS_NS
