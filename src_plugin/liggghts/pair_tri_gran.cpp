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
  const int a = task.swapped ? task.j : task.i, b = task.swapped ? task.i : task.j;
  tri::InteractionSettings s = settings_.interaction;
  s.coefficients = materials_.get(atom->type[a], atom->type[b]);
  // The history is stored as seen from (i, j); the kernel sees it from (a, b). Swapping the
  // roles negates the values that flip sign, exactly, as LIGGGHTS does for the partner. During
  // setup LIGGGHTS evaluates forces without advancing the history (shearupdate off), so a
  // restarted run continues bit for bit: work on a copy then.
  double scratch_history[tri::kHistoryDoubles];
  double *history = task.history;
  if (history && (task.swapped || !update_history)) {
    for (int v = 0; v < tri::kHistoryDoubles; ++v)
      scratch_history[v] =
          task.swapped && tri::history_flips_sign(v) ? -task.history[v] : task.history[v];
    history = scratch_history;
  }
  results_[k] = tri::body_interaction(particles_->body(a), particles_->body(b), s, dt, history,
                                      scratch_[thread], thread_tally_[thread].distance);
  if (task.history && task.swapped && update_history)
    for (int v = 0; v < tri::kHistoryDoubles; ++v)
      task.history[v] = tri::history_flips_sign(v) ? -scratch_history[v] : scratch_history[v];
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
      tasks_.push_back({i, j, atom->tag[j] < atom->tag[i], history, touching});
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

  // One thread: the sums do not depend on the thread count.
  tally_ = tri::InteractionTally{};
  for (const tri::InteractionTally &t : thread_tally_)
    tally_.distance += t.distance;
  const tagint *tag = atom->tag;
  contributions_.clear();
  for (long k = 0; k < ntasks; ++k) {
    const Task &t = tasks_[k];
    const tri::PairForceResult &r = results_[k];
    tally_.add(r);
    if (t.touching)
      *t.touching = std::any_of(t.history, t.history + tri::kHistoryDoubles,
                                [](double v) { return v != 0.0; });
    if (r.contacts_after == 0)
      continue;
    // r is the force on the pair's first atom (a) and the torques on both.
    const int a = t.swapped ? t.j : t.i, b = t.swapped ? t.i : t.j;
    Contribution ca{a, tag[b], {}, {}}, cb{b, tag[a], {}, {}};
    for (int d = 0; d < 3; ++d) {
      ca.force[d] = r.force_a[d];
      ca.torque[d] = r.torque_a[d];
      cb.force[d] = -r.force_a[d];
      cb.torque[d] = r.torque_b[d];
    }
    for (const Contribution &c : {ca, cb})
      if (newton || c.atom < nlocal) // a is i or j; i is always owned
        contributions_.push_back(c);
  }
  // Stable: two images of one partner (a periodic box smaller than a particle's reach) keep
  // the neighbour-list order.
  std::stable_sort(contributions_.begin(), contributions_.end(),
                   [](const Contribution &x, const Contribution &y) {
                     return x.atom != y.atom ? x.atom < y.atom : x.partner < y.partner;
                   });
  for (const Contribution &c : contributions_)
    for (int d = 0; d < 3; ++d) {
      f[c.atom][d] += c.force[d];
      torque[c.atom][d] += c.torque[d];
    }
}
