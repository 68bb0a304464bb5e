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
// Log: every change of dt is a line "tri/adapt_dt: step N: dt A -> B (why)", at most
// kLinesPerWindow of them per window of `log` steps (default 1000); the changes past that are
// counted and summed up in one line at the end of the window (how many of each rule, the
// smallest and largest dt). `log all`: every change. A run that oscillates between two rules
// therefore writes a few lines per thousand steps, not one a step.
//
// Stuck at dtmin: real surfaces that intersect (compute tri/stats' penetrations > 0) are not
// by themselves an error: the contact force keeps growing through the intersection
// (penetration_depth.h), so a soft or fast impact bounces out again, and one deeper than the
// model resolves is stopped by the run-safety check. What halving cannot mend is bodies that
// stay intersected: when dt has been at dtmin, with some real surfaces intersecting at every
// step, for kStuckSteps steps and for longer than two of the longest contact times
// pi sqrt(meff / kn) of the deck's materials (no impact, even a damped one, keeps bodies
// together that long: they rest or are pressed on each other through their soft layers), the
// run stops with an error naming a pair (or a particle and a wall), the deepest overlap in
// units of the combined soft layer, and what to change (a stiffer kn, a wider epsilon, a lower
// dtmin).
//
//   fix ID all tri/adapt_dt dtmax DT dtmin DT [fraction F] [growth G] [approach A]
//                           [log N|all]
//
// f_ID[1] dt, [2] halvings, [3] growths, [4] steps whose dt the approach bound lowered.
#pragma once

#include "fix.h"

#include <string>

namespace tri {
struct InteractionTally;
}

namespace LAMMPS_NS {

class FixTriAdaptDt : public Fix {
public:
  FixTriAdaptDt(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  void post_run() override;
  double compute_vector(int) override;

private:
  class FixTriParticles *particles_ = nullptr;
  double dtmax_ = 0.0, dtmin_ = 0.0, fraction_ = 0.2, growth_ = 1.1, approach_ = 0.5;
  long long halvings_ = 0, growths_ = 0, limits_ = 0;
  static constexpr int kLinesPerWindow = 10;
  static constexpr int kStuckSteps = 10;
  long log_window_ = 1000; // steps; 0: every change
  // The current log window: its first step, the lines written, the changes not written.
  struct LogWindow {
    long long first_step = -1;
    int lines = 0;
    long long quiet_halvings = 0, quiet_growths = 0, quiet_limits = 0;
    double dt_min = 0.0, dt_max = 0.0;
  } window_;
  int stuck_steps_ = 0;      // consecutive steps at dtmin with intersecting surfaces
  double stuck_time_ = 0.0;  // s, their duration
  double contact_time_ = 0.0; // s, the longest contact time (material_scales.h), at setup
  void close_log_window(long long last_step);
  void check_stuck(const tri::InteractionTally &t);
  // The largest dt the approach bound allows now (same on every rank); if below `dt`, `why`
  // says which pair or particle sets it.
  double approach_limit(double dt, std::string &why) const;
  void set_dt(double dt, const char *why);
};

} // namespace LAMMPS_NS
