#include "compute_tri_stats.h"

#include "error.h"
#include "update.h"

#include <cmath>
#include <string>

using namespace LAMMPS_NS;

namespace {
constexpr int kFixed = 11;
constexpr int kLength = kFixed + tri::kMaxPenaltyIterations + 1;
} // namespace

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
  size_vector = kLength;
  extvector = 0;
  vector = new double[kLength];
}

ComputeTriStats::~ComputeTriStats() { delete[] vector; }

void ComputeTriStats::init() {
  const tri_liggghts::GlobalTally g = tri_liggghts::global_tally(lmp);
  if (!g.have_pair && g.walls == 0)
    error->all(FLERR, "Compute tri/stats requires pair_style tri/gran or fix tri/wall");
}

void ComputeTriStats::compute_vector() {
  invoked_vector = update->ntimestep;
  const tri_liggghts::GlobalTally g = tri_liggghts::global_tally(lmp, source_);
  const tri::InteractionTally &t = g.all;
  const double fixed[kFixed] = {double(t.body_pairs_checked),
                                double(t.body_pairs_in_contact),
                                double(t.distance.triangle_pairs_tested),
                                double(t.distance.triangle_pairs_culled),
                                double(t.contacts_before),
                                double(t.contacts_after),
                                double(t.distance.fallbacks),
                                double(t.distance.penalty_pairs),
                                double(t.penetrations),
                                t.max_overlap,
                                std::isfinite(t.min_distance) ? t.min_distance : 0.0};
  for (int k = 0; k < kFixed; ++k)
    vector[k] = fixed[k];
  for (int k = 0; k <= tri::kMaxPenaltyIterations; ++k)
    vector[kFixed + k] = double(t.distance.newton_histogram[k]);
}
