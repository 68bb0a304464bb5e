#include "pair_tri_gran.h"

#include "fix_tri_particles.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "neigh_list.h"
#include "update.h"

#include <omp.h>

#include <algorithm>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
const char *kStyle = "Pair tri/gran";
}

PairTriGran::PairTriGran(LAMMPS *lmp) : PairGran(lmp) {
  settings_.interaction.coefficients.limit_force = true; // repulsive only, as in the paper
}

void PairTriGran::settings(int narg, char **arg) {
  for (int i = 0; i < narg;) {
    if (!tri_liggghts::parse_contact_keyword(narg, arg, &i, settings_, kStyle, error)) {
      const std::string msg = std::string(kStyle) + ": unknown keyword '" + arg[i] + "'";
      error->all(FLERR, msg.c_str());
    }
  }
  if (settings_.interaction.coefficients.tangential == tri::TangentialModel::history &&
      dnum_pairgran == 0) {
    // One LIGGGHTS history value per double of tri::kHistoryDoubles. Normals and shear
    // displacements change sign when LIGGGHTS swaps the roles of i and j ("1"); see
    // contact_history.h for the slot layout.
    for (int k = 0; k < tri::kHistoryDoubles; ++k)
      add_history_value("tri_history_" + std::to_string(k), tri::history_flips_sign(k) ? "1" : "0");
  }
}

void PairTriGran::init_granular() {
  particles_ = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0));
  if (!particles_)
    error->all(FLERR, "Pair tri/gran requires fix tri/particles (define it before the run)");
  materials_.load(lmp, atom->ntypes, settings_.interaction.coefficients, "pair tri/gran");
}

void PairTriGran::interact(long k, int thread, double dt, bool update_history) {
  const Task &task = tasks_[k];
  const int i = task.i, j = task.j;
  tri::InteractionSettings s = settings_.interaction;
  s.coefficients = materials_.get(atom->type[i], atom->type[j]);
  // During setup LIGGGHTS evaluates forces without advancing the history (shearupdate off),
  // so a restarted run continues bit for bit: work on a copy then.
  double scratch_history[tri::kHistoryDoubles];
  double *history = task.history;
  if (history && !update_history) {
    std::memcpy(scratch_history, history, sizeof(scratch_history));
    history = scratch_history;
  }
  results_[k] =
      tri::body_interaction(particles_->body(i), particles_->body(j), s, dt, history, scratch_[thread],
                            thread_tally_[thread].distance);
}

void PairTriGran::compute_force(int eflag, int vflag, int) {
  // Granular styles tally no pair energy or virial (as LIGGGHTS's own PairGran styles).
  evflag = vflag_fdotr = 0;
  double **f = atom->f, **torque = atom->torque;
  const int nlocal = atom->nlocal;
  const bool newton = force->newton_pair;
  const double dt = update->dt;
  double **first_history = listgranhistory ? listgranhistory->firstdouble : nullptr;
  int **first_touch = listgranhistory ? listgranhistory->firstneigh : nullptr;
  const int dnum = this->dnum();

  tasks_.clear();
  for (int ii = 0; ii < list->inum; ++ii) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; ++jj) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx = atom->x[i][0] - atom->x[j][0], dy = atom->x[i][1] - atom->x[j][1],
                   dz = atom->x[i][2] - atom->x[j][2];
      const double reach = atom->radius[i] + atom->radius[j];
      double *history = first_history ? &first_history[i][dnum * jj] : nullptr;
      int *touching = first_touch ? &first_touch[i][jj] : nullptr;
      if (dx * dx + dy * dy + dz * dz >= reach * reach) {
        if (history) { // apart: the contact, if there was one, has ended
          std::fill(history, history + tri::kHistoryDoubles, 0.0);
          *touching = 0;
        }
        continue;
      }
      tasks_.push_back({i, j, history, touching});
    }
  }
  results_.assign(tasks_.size(), tri::PairForceResult{});

  const int nthreads = tri_liggghts::pair_loop_threads(settings_.loop, tasks_.size());
  if (static_cast<int>(scratch_.size()) < nthreads)
    scratch_.resize(nthreads);
  thread_tally_.assign(nthreads, tri::InteractionTally{});
  const bool update_history = shearupdate_ != 0;
  const long ntasks = static_cast<long>(tasks_.size());
  if (settings_.loop == tri_liggghts::PairLoop::particle_pairs) {
#pragma omp parallel for schedule(dynamic, 4) num_threads(nthreads)
    for (long k = 0; k < ntasks; ++k)
      interact(k, omp_get_thread_num(), dt, update_history);
  } else {
    for (long k = 0; k < ntasks; ++k)
      interact(k, 0, dt, update_history);
  }

  // One thread, neighbour-list order: the sums do not depend on the thread count.
  tally_ = tri::InteractionTally{};
  for (const tri::InteractionTally &t : thread_tally_)
    tally_.distance += t.distance;
  for (long k = 0; k < ntasks; ++k) {
    const Task &t = tasks_[k];
    const tri::PairForceResult &r = results_[k];
    tally_.add(r);
    if (t.touching)
      *t.touching = std::any_of(t.history, t.history + tri::kHistoryDoubles,
                                [](double v) { return v != 0.0; });
    if (r.contacts_after == 0)
      continue;
    for (int d = 0; d < 3; ++d) {
      f[t.i][d] += r.force_a[d];
      torque[t.i][d] += r.torque_a[d];
    }
    if (newton || t.j < nlocal)
      for (int d = 0; d < 3; ++d) {
        f[t.j][d] -= r.force_a[d];
        torque[t.j][d] += r.torque_b[d];
      }
  }
}
