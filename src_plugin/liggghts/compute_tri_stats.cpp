#include "compute_tri_stats.h"

#include "fix_tri_particles.h"

#include "error.h"
#include "modify.h"
#include "update.h"

#include <cmath>
#include <string>

using namespace LAMMPS_NS;

ComputeTriStats::ComputeTriStats(LAMMPS *lmp, int &iarg, int narg, char **arg)
    : Compute(lmp, iarg, narg, arg) {
  if (iarg < narg) {
    const std::string which = arg[iarg++];
    if (which == "pair")
      source_ = tri_liggghts::TallySource::pair;
    else if (which == "wall")
      source_ = tri_liggghts::TallySource::wall;
    else if (which != "all") {
      const std::string msg = "Compute tri/stats: expected all, pair or wall, got '" + which + "'";
      error->all(FLERR, msg.c_str());
    }
  }
  if (iarg < narg) {
    const std::string msg = std::string("Compute tri/stats: unknown keyword '") + arg[iarg] + "'";
    error->all(FLERR, msg.c_str());
  }
  vector_flag = 1;
  size_vector = static_cast<int>(tri::stats_columns().size());
  extvector = 0;
  vector = new double[size_vector];
}

ComputeTriStats::~ComputeTriStats() { delete[] vector; }

void ComputeTriStats::init() {
  particles_ = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0));
  if (!particles_)
    error->all(FLERR, "Compute tri/stats requires fix tri/particles");
  const tri_liggghts::ContactBoard &board = particles_->board();
  if (board.sources(tri_liggghts::SourceKind::particle_pairs) +
          board.sources(tri_liggghts::SourceKind::walls) ==
      0)
    error->all(FLERR, "Compute tri/stats requires pair_style tri/gran or fix tri/wall");
}

void ComputeTriStats::compute_vector() {
  invoked_vector = update->ntimestep;
  const tri::InteractionTally t = tri_liggghts::global_tally(particles_->published(), world, source_);
  const std::vector<tri::StatColumn> &columns = tri::stats_columns();
  for (std::size_t k = 0; k < columns.size(); ++k) {
    const double v = columns[k].value(t);
    vector[k] = std::isfinite(v) ? v : 0.0; // the closest distance when nothing was tested
  }
}
