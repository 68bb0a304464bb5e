#include "fix_tri_adapt_dt.h"

#include "approach_speed.h"
#include "fix_tri_particles.h"
#include "material_scales.h"
#include "step_tally.h"

#include "comm.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "neighbor.h"
#include "pair.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include <mpi.h>

using namespace LAMMPS_NS;
using namespace FixConst;

FixTriAdaptDt::FixTriAdaptDt(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {
  bool have_max = false, have_min = false;
  for (int i = 3; i < narg; i += 2) {
    const std::string key = arg[i];
    if (key == "log" && i + 1 < narg && std::string(arg[i + 1]) == "all") {
      log_window_ = 0;
      continue;
    }
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
    } else if (key == "approach") {
      approach_ = v;
    } else if (key == "log") {
      if (v != std::floor(v) || v > 1e12) {
        const std::string msg = "Fix tri/adapt_dt: 'log' expects a number of steps or 'all', "
                                "got '" + std::string(arg[i + 1]) + "'";
        error->all(FLERR, msg.c_str());
      }
      log_window_ = static_cast<long>(v);
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
  size_vector = 4;
  global_freq = 1;
  extvector = 0;
}

int FixTriAdaptDt::setmask() { return END_OF_STEP; }

void FixTriAdaptDt::init() {
  particles_ = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0));
  if (!particles_)
    error->all(FLERR, "Fix tri/adapt_dt requires fix tri/particles");
  particles_->board().publish_adaptive_dt(dtmin_, dtmax_); // for the time-step check
  if (update->dt > dtmax_ || update->dt < dtmin_)
    set_dt(std::min(std::max(update->dt, dtmin_), dtmax_), "outside [dtmin, dtmax]");
}

namespace {
void write_line(FILE *screen, FILE *logfile, const char *line) {
  if (screen)
    std::fputs(line, screen);
  if (logfile)
    std::fputs(line, logfile);
}
} // namespace

// One summary line for the changes of the window that were not written one by one.
void FixTriAdaptDt::close_log_window(long long last_step) {
  const long long quiet = window_.quiet_halvings + window_.quiet_growths + window_.quiet_limits;
  if (quiet > 0 && comm->me == 0) {
    char line[400];
    std::snprintf(line, sizeof line,
                  "tri/adapt_dt: steps %lld-%lld: %lld more changes not listed (%lld halvings, "
                  "%lld growths, %lld approach bounds), dt between %g and %g, now %g\n",
                  window_.first_step, last_step, quiet, window_.quiet_halvings,
                  window_.quiet_growths, window_.quiet_limits, window_.dt_min, window_.dt_max,
                  update->dt);
    write_line(screen, logfile, line);
  }
  window_ = LogWindow{};
}

void FixTriAdaptDt::post_run() { close_log_window(update->ntimestep); }

void FixTriAdaptDt::set_dt(double dt, const char *why) {
  if (dt == update->dt)
    return;
  const long long step = update->ntimestep;
  if (log_window_ > 0 && window_.first_step >= 0 && step >= window_.first_step + log_window_)
    close_log_window(step - 1);
  if (window_.first_step < 0) {
    window_.first_step = step;
    window_.dt_min = window_.dt_max = update->dt;
  }
  window_.dt_min = std::min(window_.dt_min, dt);
  window_.dt_max = std::max(window_.dt_max, dt);
  if (log_window_ == 0 || window_.lines < kLinesPerWindow) {
    ++window_.lines;
    if (comm->me == 0) {
      char line[256];
      std::snprintf(line, sizeof line, "tri/adapt_dt: step " BIGINT_FORMAT ": dt %g -> %g (%s)\n",
                    update->ntimestep, update->dt, dt, why);
      write_line(screen, logfile, line);
    }
  } else if (std::strncmp(why, "approach", 8) == 0) {
    ++window_.quiet_limits;
  } else if (dt < update->dt) {
    ++window_.quiet_halvings;
  } else {
    ++window_.quiet_growths;
  }
  update->update_time();
  update->dt = dt;
  if (force->pair)
    force->pair->reset_dt();
  for (int i = 0; i < modify->nfix; ++i)
    modify->fix[i]->reset_dt();
}

double FixTriAdaptDt::approach_limit(double dt, std::string &why) const {
  const tri_liggghts::PairApproach pairs =
      tri_liggghts::pair_dt_limit(lmp, particles_->board(), approach_ * particles_->epsilon());
  const tri_liggghts::FastestParticle fastest = tri_liggghts::fastest_particle(lmp);
  const double skin_limit = fastest.speed > 0.0 ? 0.5 * neighbor->skin / fastest.speed
                                                : std::numeric_limits<double>::infinity();
  double local[2] = {pairs.dt_limit, skin_limit}, global[2];
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MIN, world);
  // The reason names the pair (or particle) on the rank that holds it; only rank 0 prints,
  // so the figures travel with a second reduction only when the bound applies.
  const bool by_pair = global[0] <= global[1];
  const double limit = std::min(global[0], global[1]);
  if (!(limit < dt))
    return limit;
  struct {
    double value;
    int rank;
  } mine{by_pair ? pairs.dt_limit : skin_limit, comm->me}, owner;
  MPI_Allreduce(&mine, &owner, 1, MPI_DOUBLE_INT, MPI_MINLOC, world);
  double info[3] = {by_pair ? pairs.speed : fastest.speed,
                    double(by_pair ? pairs.tag_i : fastest.tag), double(pairs.tag_j)};
  MPI_Bcast(info, 3, MPI_DOUBLE, owner.rank, world);
  char text[200];
  if (by_pair)
    std::snprintf(text, sizeof text,
                  "approach: particles %.0f and %.0f close in at %.4g m/s, approach * epsilon",
                  info[1], info[2], info[0]);
  else
    std::snprintf(text, sizeof text,
                  "approach: particle %.0f moves at %.4g m/s, half the neighbour skin", info[1],
                  info[0]);
  why = text;
  return limit;
}

// Before the first step, so that particles launched at each other start with a bounded dt.
void FixTriAdaptDt::setup(int) {
  // Here, not in init(): a fix tri/wall defined after this fix joins the board in its init().
  const tri_liggghts::ContactBoard &board = particles_->board();
  if (board.sources(tri_liggghts::SourceKind::particle_pairs) +
          board.sources(tri_liggghts::SourceKind::walls) ==
      0)
    error->all(FLERR, "Fix tri/adapt_dt requires pair_style tri/gran or fix tri/wall");
  contact_time_ = tri_liggghts::longest_contact_time(board, particles_->type_bodies());
  stuck_steps_ = 0;
  stuck_time_ = 0.0;
  std::string why;
  const double limit = approach_limit(update->dt, why);
  if (limit < update->dt && update->dt > dtmin_) {
    ++limits_;
    set_dt(std::max(limit, dtmin_), why.c_str());
  }
}

// Real surfaces intersect while dt cannot go lower: the soft layer is overrun for good.
void FixTriAdaptDt::check_stuck(const tri::InteractionTally &t) {
  const bool stuck = update->dt <= dtmin_ && t.penetrations > 0;
  stuck_steps_ = stuck ? stuck_steps_ + 1 : 0;
  stuck_time_ = stuck ? stuck_time_ + update->dt : 0.0;
  if (stuck_steps_ < kStuckSteps || stuck_time_ < 2.0 * contact_time_)
    return;
  const tri_liggghts::ContactBoard &board = particles_->board();
  tri_liggghts::IntersectingPair p = board.first_intersecting(tri_liggghts::SourceKind::particle_pairs);
  if (!p.found())
    p = board.first_intersecting(tri_liggghts::SourceKind::walls);
  double tags[2] = {double(p.tag_a), double(p.tag_b)}, found[2];
  MPI_Allreduce(tags, found, 2, MPI_DOUBLE, MPI_MAX, world);
  char who[120];
  if (found[1] > 0.0)
    std::snprintf(who, sizeof who, "e.g. particles %.0f and %.0f", found[0], found[1]);
  else
    std::snprintf(who, sizeof who, "e.g. particle %.0f and a wall", found[0]);
  const double layer = 2.0 * particles_->epsilon();
  char msg[700];
  std::snprintf(msg, sizeof msg,
                "Fix tri/adapt_dt: step " BIGINT_FORMAT ": dt has been at dtmin (%g s) for %d "
                "steps (%g s, two contact times %g s: longer than any bounce) while real "
                "surfaces intersect (%lld interaction(s), %s; deepest overlap %g m = %.3g x the "
                "combined soft layer 2 epsilon): the contact force cannot push them apart at "
                "this stiffness; use a stiffer kn, a wider epsilon, or a lower dtmin",
                update->ntimestep, dtmin_, stuck_steps_, stuck_time_, 2.0 * contact_time_,
                t.penetrations, who, t.max_overlap, t.max_overlap / layer);
  error->all(FLERR, msg);
}

void FixTriAdaptDt::end_of_step() {
  const tri::InteractionTally t = tri_liggghts::global_tally(particles_->board(), world);
  check_stuck(t);
  double dt = update->dt;
  enum { keep, halve, grow } rule = keep;
  if (t.contacts_after > 0 && t.min_distance < fraction_ * particles_->epsilon()) {
    if (dt > dtmin_) {
      rule = halve;
      dt = std::max(0.5 * dt, dtmin_);
    }
  } else if (t.contacts_after == 0 && dt < dtmax_) {
    rule = grow;
    dt = std::min(growth_ * dt, dtmax_);
  }
  std::string approach_why;
  const double limit = approach_limit(dt, approach_why);
  // A bound within 1e-6 of the current dt (a pair flying in at constant speed) is no change.
  if (limit < dt && dt > dtmin_) {
    const double bounded = std::max(limit, dtmin_);
    if (std::fabs(bounded - update->dt) > 1e-6 * update->dt) {
      ++limits_;
      set_dt(bounded, approach_why.c_str());
    }
  } else if (rule == halve) {
    ++halvings_;
    set_dt(dt, "a contact closer than fraction * epsilon");
  } else if (rule == grow) {
    ++growths_;
    set_dt(dt, "no contact");
  }
}

double FixTriAdaptDt::compute_vector(int k) {
  if (k == 0)
    return update->dt;
  if (k == 3)
    return double(limits_);
  return k == 1 ? double(halvings_) : double(growths_);
}
