#include "fix_tri_adapt_dt.h"

#include "fix_tri_particles.h"
#include "step_tally.h"

#include "comm.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "pair.h"
#include "update.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

FixTriAdaptDt::FixTriAdaptDt(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {
  bool have_max = false, have_min = false;
  for (int i = 3; i < narg; i += 2) {
    const std::string key = arg[i];
    if (i + 1 >= narg) {
      const std::string msg = "Fix tri/adapt_dt: missing value after '" + key + "'";
      error->all(FLERR, msg.c_str());
    }
    char *end = nullptr;
    const double v = std::strtod(arg[i + 1], &end);
    if (*end != '\0' || !(v > 0.0)) {
      const std::string msg =
          "Fix tri/adapt_dt: '" + key + "' must be a positive number, got '" + arg[i + 1] + "'";
      error->all(FLERR, msg.c_str());
    }
    if (key == "dtmax") {
      dtmax_ = v;
      have_max = true;
    } else if (key == "dtmin") {
      dtmin_ = v;
      have_min = true;
    } else if (key == "fraction") {
      fraction_ = v;
    } else if (key == "growth") {
      if (v <= 1.0)
        error->all(FLERR, "Fix tri/adapt_dt: 'growth' must be > 1");
      growth_ = v;
    } else {
      const std::string msg = "Fix tri/adapt_dt: unknown keyword '" + key + "'";
      error->all(FLERR, msg.c_str());
    }
  }
  if (!have_max || !have_min)
    error->all(FLERR, "Fix tri/adapt_dt needs 'dtmax' and 'dtmin'");
  if (dtmin_ > dtmax_)
    error->all(FLERR, "Fix tri/adapt_dt: dtmin must not exceed dtmax");
  nevery = 1;
  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extvector = 0;
}

int FixTriAdaptDt::setmask() { return END_OF_STEP; }

void FixTriAdaptDt::init() {
  particles_ = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0));
  if (!particles_)
    error->all(FLERR, "Fix tri/adapt_dt requires fix tri/particles");
  const tri_liggghts::GlobalTally g = tri_liggghts::global_tally(lmp);
  if (!g.have_pair && g.walls == 0)
    error->all(FLERR, "Fix tri/adapt_dt requires pair_style tri/gran or fix tri/wall");
  if (update->dt > dtmax_ || update->dt < dtmin_)
    set_dt(std::min(std::max(update->dt, dtmin_), dtmax_), "outside [dtmin, dtmax]");
}

void FixTriAdaptDt::set_dt(double dt, const char *why) {
  if (dt == update->dt)
    return;
  if (comm->me == 0) {
    char line[256];
    std::snprintf(line, sizeof line, "tri/adapt_dt: step " BIGINT_FORMAT ": dt %g -> %g (%s)\n",
                  update->ntimestep, update->dt, dt, why);
    if (screen)
      std::fputs(line, screen);
    if (logfile)
      std::fputs(line, logfile);
  }
  update->update_time();
  update->dt = dt;
  if (force->pair)
    force->pair->reset_dt();
  for (int i = 0; i < modify->nfix; ++i)
    modify->fix[i]->reset_dt();
}

void FixTriAdaptDt::end_of_step() {
  const tri::InteractionTally t = tri_liggghts::global_tally(lmp).all;
  if (t.contacts_after > 0 && t.min_distance < fraction_ * particles_->epsilon()) {
    if (update->dt > dtmin_) {
      ++halvings_;
      set_dt(std::max(0.5 * update->dt, dtmin_), "a contact closer than fraction * epsilon");
    }
  } else if (t.contacts_after == 0 && update->dt < dtmax_) {
    ++growths_;
    set_dt(std::min(growth_ * update->dt, dtmax_), "no contact");
  }
}

double FixTriAdaptDt::compute_vector(int k) {
  if (k == 0)
    return update->dt;
  return k == 1 ? double(halvings_) : double(growths_);
}
