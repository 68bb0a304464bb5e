#include "pair_tri_gran.h"

#include "fix_tri_particles.h"
#include "incompatible_styles.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "domain.h"
#include "fix_tri_kept_contacts.h"
#include "force.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <string>

#include <omp.h>

using namespace LAMMPS_NS;

namespace {
const char *kStyle = "Pair tri/gran";
}

PairTriGran::PairTriGran(LAMMPS *lmp) : PairGran(lmp) {
  settings_.interaction.coefficients.limit_force = true; // repulsive only, as in the paper
  // The forces act at contact points, not along the line of centres: the virial is tallied per
  // contact (branch vectors to the contact points), never from f . r.
  no_virial_fdotr_compute = 1;
}

void PairTriGran::settings(int narg, char **arg) {
  for (int i = 0; i < narg;) {
    if (!tri_liggghts::parse_contact_keyword(narg, arg, &i, settings_, kStyle, error)) {
      std::string msg =
          tri_liggghts::gran_submodel_message(kStyle, arg[i], i + 1 < narg ? arg[i + 1] : nullptr);
      if (msg.empty())
        msg = std::string(kStyle) + ": unknown keyword '" + arg[i] + "'";
      error->all(FLERR, msg.c_str());
    }
  }
  if (dnum_pairgran == 0) {
    // One LIGGGHTS history value per double of tri::kHistoryDoubles. Normals and shear
    // displacements change sign when LIGGGHTS swaps the roles of i and j ("1"); see
    // contact_history.h for the slot layout.
    if (settings_.interaction.coefficients.tangential == tri::TangentialModel::history)
      for (int k = 0; k < tri::kHistoryDoubles; ++k)
        add_history_value("tri_history_" + std::to_string(k),
                          tri::history_flips_sign(k) ? "1" : "0");
    // Then the separating axis (from i towards j: it changes sign with the roles).
    axis_offset_ = dnum_pairgran;
    for (int k = 0; k < 3; ++k)
      add_history_value("tri_axis_" + std::to_string(k), "1");
  }
}

void PairTriGran::init_style() {
  particles_ = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0));
  if (!particles_)
    error->all(FLERR, "Pair tri/gran requires fix tri/particles (define it before the run)");
  materials_.load(lmp, atom->ntypes, settings_.interaction, settings_.model,
                  particles_->type_bodies().sphere, false, "pair tri/gran");
  tri_liggghts::ContactBoard &board = particles_->board();
  board_slot_ = board.join("pair", tri_liggghts::SourceKind::particle_pairs);
  std::vector<int> types(atom->ntypes);
  for (int t = 1; t <= atom->ntypes; ++t)
    types[t - 1] = t;
  board.publish_material(board_slot_, materials_.hint(atom->ntypes, types));
  particles_->resolve_epsilon(); // before PairGran sizes the cutoffs from the radii
  PairGran::init_style();
  find_kept_contacts();
}

// The fix that keeps the pairs' contact points between steps and moves them with the atoms
// (fix_tri_kept_contacts.h): created once, like LIGGGHTS's fix contacthistory, under a fixed ID
// so that a restart file's records find it again.
void PairTriGran::find_kept_contacts() {
  kept_ = nullptr;
  if (!(settings_.interaction.kept_tolerance > 0.0))
    return;
  const char *id = "tri_kept_contacts";
  int f = modify->find_fix(id);
  if (f < 0) {
    char *args[] = {const_cast<char *>(id), const_cast<char *>("all"),
                    const_cast<char *>("tri/kept_contacts")};
    modify->add_fix(3, args);
    f = modify->find_fix(id);
  }
  if (f < 0 || std::string(modify->fix[f]->style) != "tri/kept_contacts")
    error->all(FLERR, "Pair tri/gran: fix ID 'tri_kept_contacts' is taken by another fix");
  kept_ = &static_cast<FixTriKeptContacts *>(modify->fix[f])->store();
}

// The step's tasks, in the order of the neighbour list. On several threads each lists a
// contiguous run of rows (about as many neighbour pairs each) into a list of its own, and the
// lists are then joined in row order: the same tasks, in the same order, as one thread lists.
// Every ask of the stores for one pair's key comes from the thread that lists its row, so each
// store hands its entries out as in the serial order (candidate_store.h).
void PairTriGran::collect_tasks() {
  const int inum = list->inum;
  std::size_t neighbour_pairs = 0;
  for (int ii = 0; ii < inum; ++ii)
    neighbour_pairs += static_cast<std::size_t>(list->numneigh[list->ilist[ii]]);
  const int threads = tri_liggghts::pair_loop_threads(settings_.loop, neighbour_pairs);
  candidates_.begin_step(neighbour_pairs, threads);
  if (kept_)
    kept_->begin_step(neighbour_pairs);
  tasks_.clear();
  passed_.clear();
  if (threads <= 1) {
    collect_rows({0, inum, 0}, 0, tasks_, passed_);
  } else {
    if (static_cast<int>(row_lists_.size()) < threads)
      row_lists_.resize(static_cast<std::size_t>(threads));
    std::vector<RowRange> ranges = split_rows(neighbour_pairs, threads);
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num();
      RowList &own = row_lists_[static_cast<std::size_t>(t)];
      own.tasks.clear();
      own.passed.clear();
      collect_rows(ranges[static_cast<std::size_t>(t)], t, own.tasks, own.passed);
#pragma omp barrier
#pragma omp single
      {
        std::size_t tasks = 0, passed = 0;
        for (int u = 0; u < threads; ++u) {
          tasks += row_lists_[static_cast<std::size_t>(u)].tasks.size();
          passed += row_lists_[static_cast<std::size_t>(u)].passed.size();
        }
        tasks_.resize(tasks);
        passed_.resize(passed);
      }
      std::size_t task_offset = 0, passed_offset = 0;
      for (int u = 0; u < t; ++u) {
        task_offset += row_lists_[static_cast<std::size_t>(u)].tasks.size();
        passed_offset += row_lists_[static_cast<std::size_t>(u)].passed.size();
      }
      std::copy(own.tasks.begin(), own.tasks.end(), tasks_.begin() + static_cast<long>(task_offset));
      for (std::size_t p = 0; p < own.passed.size(); ++p) {
        passed_[passed_offset + p] = own.passed[p];
        passed_[passed_offset + p].before += task_offset;
      }
    }
  }
  candidates_.end_step();
}

// Rows [first, last) of the neighbour list in `threads` runs of about equal neighbour pairs.
std::vector<PairTriGran::RowRange> PairTriGran::split_rows(std::size_t neighbour_pairs,
                                                           int threads) const {
  std::vector<RowRange> ranges(static_cast<std::size_t>(threads));
  int ii = 0;
  std::size_t slot = 0;
  for (int t = 0; t < threads; ++t) {
    const std::size_t until = neighbour_pairs * static_cast<std::size_t>(t + 1) /
                              static_cast<std::size_t>(threads);
    ranges[static_cast<std::size_t>(t)].first = ii;
    ranges[static_cast<std::size_t>(t)].slot = slot;
    for (; ii < list->inum && (slot < until || t == threads - 1); ++ii)
      slot += static_cast<std::size_t>(list->numneigh[list->ilist[ii]]);
    ranges[static_cast<std::size_t>(t)].last = ii;
  }
  return ranges;
}

// The tasks of neighbour rows [rows.first, rows.last), whose first pair is the stores' slot
// rows.slot, appended to `tasks` and `passed` (`before` counting the tasks of `tasks`).
void PairTriGran::collect_rows(RowRange rows, int lane, std::vector<Task> &tasks,
                               std::vector<PassedPair> &passed) {
  double **first_history = listgranhistory ? listgranhistory->firstdouble : nullptr;
  int **first_touch = listgranhistory ? listgranhistory->firstneigh : nullptr;
  const int dnum = this->dnum();
  const bool tangential =
      settings_.interaction.coefficients.tangential == tri::TangentialModel::history;
  const bool coherent = settings_.interaction.coherence > 0.0;
  // The stores' hint slots: a pair's place in the neighbour list, which stays the same until the
  // next rebuild (counting only the pairs within reach, every pair after one that came within
  // reach or left it named another's entry, and was looked up).
  std::size_t slot = rows.slot;
  const double lift = particles_->largest_lift();
  const double cutoff =
      tri::particle_pair_cutoff(particles_->epsilon(), particles_->epsilon(), lift, lift);
  // Every neighbour pair every step, most of them apart: the arrays in locals, which the
  // stores below cannot change (through atom-> they are reloaded for every pair).
  double *const *const x = atom->x;
  const double *const radius = atom->radius;
  const tagint *const tag = atom->tag;
  const int *const ilist = list->ilist, *const numneigh = list->numneigh;
  int *const *const firstneigh = list->firstneigh;
  for (int ii = rows.first; ii < rows.last; ++ii) {
    const int i = ilist[ii];
    const int *jlist = firstneigh[i];
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2], ri = radius[i];
    const int jnum = numneigh[i];
    for (int jj = 0; jj < jnum; ++jj, ++slot) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx = xi - x[j][0], dy = yi - x[j][1], dz = zi - x[j][2];
      const double reach = ri + radius[j];
      double *values = first_history ? &first_history[i][dnum * jj] : nullptr;
      int *touching = first_touch ? &first_touch[i][jj] : nullptr;
      if (dx * dx + dy * dy + dz * dz >= reach * reach) {
        // Apart: the contact, if there was one, has ended; the axis is dropped. Untouched
        // values are zero already (touching is set wherever one is not: below).
        if (values && *touching) {
          std::fill(values, values + dnum_pairgran, 0.0);
          *touching = 0;
        }
        continue;
      }
      double *history = values && tangential ? values : nullptr;
      double *axis = values && settings_.separation ? values + axis_offset_ : nullptr;
      tri::CandidateCache *candidates =
          coherent ? candidates_.entry(
                         slot, tri_liggghts::CandidateStore::pair_key(tag[i], tag[j]), lane)
                   : nullptr;
      const bool swapped = tag[j] < tag[i];
      if (candidates) {
        travel_.touch(*particles_, atom, i);
        travel_.touch(*particles_, atom, j);
      }
      if (candidates && // the sums are touched only where candidates are kept
          tri::proven_apart_by_travel(candidates, swapped ? travel_.of(j, i) : travel_.of(i, j),
                                      cutoff)) {
        passed.push_back({tasks.size(),
                          tri_liggghts::pair_approach(x[i], atom->v[i], ri, x[j], atom->v[j],
                                                      radius[j]),
                          tag[i], tag[j]});
        continue;
      }
      // Only a pair that touched last step can hold kept points, and with the tangential
      // history such a pair has its first slot occupied: the others are not looked up, and a
      // contact that begins keeps its points from its second step.
      const bool may_hold = !history || !tri::apart_needs_nothing(history);
      double *kept = kept_ && may_hold ? kept_->entry(slot, kept_key(i, j)) : nullptr;
      tasks.push_back({i, j, swapped, history, axis, values, touching, candidates, kept});
    }
  }
}

// The store's key of the pair (i, j), i owned (kept_contact_store.h): j is a periodic image
// where it lies outside the box along a periodic direction.
std::uint64_t PairTriGran::kept_key(int i, int j) const {
  const double *x = atom->x[j];
  bool image = false;
  for (int d = 0; d < 3; ++d)
    image = image || (domain->periodicity[d] && (x[d] < domain->boxlo[d] || x[d] >= domain->boxhi[d]));
  using Store = tri_liggghts::KeptContactStore;
  const long long ti = atom->tag[i], tj = atom->tag[j];
  const Store::Image which = !image ? Store::Image::none : ti < tj ? Store::Image::b : Store::Image::a;
  return Store::key(std::min(ti, tj), std::max(ti, tj), which);
}

PairTriGran::TaskView PairTriGran::view(const Task &task) {
  TaskView v{task.swapped ? task.j : task.i, task.swapped ? task.i : task.j,
             task.swapped ? -1.0 : 1.0, {0.0, 0.0, 0.0}};
  if (task.axis)
    for (int d = 0; d < 3; ++d)
      v.axis[d] = v.sign * task.axis[d];
  return v;
}

template <class Step>
auto PairTriGran::in_kernel_view(const Task &task, bool update_history, Step &&step) {
  TaskView v = view(task);
  // prepare() has asked proven_apart.
  const tri::SeparationCache cache{task.axis ? v.axis : nullptr, update_history, task.candidates,
                                   travel_.of(v.a, v.b), task.kept};
  const tri::InteractionSettings &s = materials_.settings(atom->type[v.a], atom->type[v.b]);
  auto out = [&] {
    // Stored as seen from (i, j); the kernel sees it from (a, b), and the view writes the
    // values back when it goes out of scope.
    tri::HistoryView history(task.history, task.swapped, update_history);
    const tri::Body *i = task.body_i ? task.body_i : &particles_->body(task.i);
    const tri::Body *j = task.body_j ? task.body_j : &particles_->body(task.j);
    return step(task.swapped ? *j : *i, task.swapped ? *i : *j, s, history.data(), cache);
  }();
  if (task.axis && update_history)
    for (int d = 0; d < 3; ++d)
      task.axis[d] = v.sign * v.axis[d];
  return out;
}

void PairTriGran::prepare(Task &task, bool update_history) {
  particles_->ensure_body_of(task.i);
  particles_->ensure_body_of(task.j);
  TaskView v = view(task);
  const tri::SeparationCache cache{task.axis ? v.axis : nullptr, update_history, task.candidates,
                                   travel_.of(v.a, v.b), task.kept};
  task.apart = tri::proven_apart(particles_->body(v.a), particles_->body(v.b),
                                 settings_.interaction, cache);
}

bool PairTriGran::carries_kept_contacts(const Task &task) {
  if (!tri::contacts_kept(task.kept))
    return false;
  const TaskView v = view(task);
  const tri::SeparationCache cache{nullptr, false, nullptr, {}, task.kept};
  return tri::kept_contacts_hold(particles_->body(v.a), particles_->body(v.b),
                                 materials_.settings(atom->type[v.a], atom->type[v.b]), cache);
}

tri::PairPlan PairTriGran::EngineHost::plan(std::size_t k, int thread,
                                            tri::InteractionScratch &scratch,
                                            tri::ContactStats &stats) {
  Task &task = style.tasks_[k];
  style.prepare(task, update_history);
  if (k + kPrefetchAhead < style.tasks_.size())
    style.prefetch(style.tasks_[k + kPrefetchAhead]);
  if (task.apart && tri::apart_needs_nothing(task.history) && !tri::kept_state(task.kept))
    return tri::apart_result(stats); // the axis stays as it is: its view would write it back
  // World-frame triangles as they are needed (a thread's recent ones): not for a pair apart or
  // one whose kept contact points are carried (both read the poses alone).
  const bool carried = !task.apart && style.carries_kept_contacts(task);
  if (!task.apart && !carried) {
    task.body_i = &style.particles_->task_body(task.i, thread, style.pins_.of(k));
    task.body_j = &style.particles_->task_body(task.j, thread, style.pins_.of(k));
  }
  return style.in_kernel_view(
      task, update_history,
      [&](const tri::Body &a, const tri::Body &b, const tri::InteractionSettings &s,
          double *history, const tri::SeparationCache &cache) -> tri::PairPlan {
        if (carried)
          return tri::carried_contacts_result(a, b, s, dt, history, scratch, stats, cache);
        if (task.apart) {
          if (update_history && tri::kept_state(task.kept))
            tri::clear_kept_contacts(task.kept);
          return tri::apart_result(a, b, s, dt, history, scratch, stats);
        }
        return tri::plan_body_pair(a, b, s, dt, history, scratch, stats, cache);
      });
}

tri::PairForceResult PairTriGran::EngineHost::finish(std::size_t k,
                                                     const tri::KernelRequest &request,
                                                     const tri::TrianglePairDistance *results,
                                                     tri::InteractionScratch &scratch,
                                                     tri::ContactStats &stats) {
  return style.in_kernel_view(
      style.tasks_[k], update_history,
      [&](const tri::Body &a, const tri::Body &b, const tri::InteractionSettings &s,
          double *history, const tri::SeparationCache &cache) {
        return tri::finish_body_pair(a, b, s, dt, history, scratch, stats, cache, request, results);
      });
}

void PairTriGran::EngineHost::complete(std::size_t k, tri::PairForceResult &r) {
  const Task &task = style.tasks_[k];
  // With newton off a pair with a ghost is evaluated by both owners' ranks (or, across a
  // periodic boundary, twice on one): half its energy each, so that compute tri/stats sums
  // every contact's energy once.
  if (!newton && task.j >= nlocal)
    r.elastic_energy *= 0.5;
  if (task.touching) { // the tangential history or the axis: LIGGGHTS keeps all or nothing
    const double *values = task.touching_values;
    // An apart pair's clear history (its slot 0 empty) is all zero: only the values after it
    // are read.
    const bool clear = task.apart && tri::apart_needs_nothing(task.history);
    const double *from = clear && task.history == values ? values + tri::kHistoryDoubles : values;
    *task.touching =
        std::any_of(from, values + style.dnum_pairgran, [](double v) { return v != 0.0; });
  }
  LAMMPS_NS::Atom *atom = style.atom;
  if (r.contacts_after > 0) { // r is the force on the pair's first atom (a)
    const int a = task.swapped ? task.j : task.i, b = task.swapped ? task.i : task.j;
    style.engine_.set_recipients(k, newton || a < nlocal ? a : -1, atom->tag[b],
                                 newton || b < nlocal ? b : -1, atom->tag[a]);
  } // (a is i or j; i is always owned)
  const tri::BodyState &si = style.particles_->body(task.i).state;
  const tri::BodyState &sj = style.particles_->body(task.j).state;
  style.task_geometry_[k] =
      tri_liggghts::pair_approach(si.x.data(), si.v.data(), atom->radius[task.i], sj.x.data(),
                                  sj.v.data(), atom->radius[task.j]);
}

// A task's kept state (candidates, contact history, axis) is scattered over the heap; asked for
// a few tasks ahead it arrives while the tasks before it run.
void PairTriGran::prefetch(const Task &t) {
  if (t.candidates)
    t.candidates->prefetch();
  if (t.touching_values)
    for (int offset = 0; offset < dnum_pairgran; offset += 8)
      __builtin_prefetch(t.touching_values + offset);
}

void PairTriGran::compute_force(int eflag, int vflag, int) {
  // No pair energy is tallied (as LIGGGHTS's own granular styles); the virial, where LIGGGHTS
  // asks for it (compute pressure, stress/atom), from each contact's record.
  if (eflag || vflag)
    ev_setup(eflag, vflag);
  else
    evflag = vflag_fdotr = 0;
  const bool virial_wanted = vflag_global || vflag_atom;
  const int nlocal = atom->nlocal;
  const bool newton = force->newton_pair;
  const double dt = update->dt;
  const bool update_history = shearupdate_ != 0;
  // Atoms are renumbered only where the neighbour lists are rebuilt (exchange, sorting,
  // insertion; the setup of a run).
  travel_.begin_step(atom, neighbor->ago == 0);
  collect_tasks();

  task_geometry_.resize(tasks_.size());
  const int nthreads = tri_liggghts::pair_loop_threads(settings_.loop, tasks_.size());
  particles_->prepare_task_bodies(nthreads);
  pins_ = particles_->reserve_pins(tasks_.size(), nthreads);
  tri_liggghts::ContactBoard &board = particles_->board();
  engine_.record_contacts(virial_wanted || board.contacts_wanted());
  EngineHost host{*this, dt, update_history, newton, nlocal};
  engine_.run(tasks_.size(), nthreads, host);
  if (engine_.failed())
    report_failure();

  const StepSummary summary = summarize(nthreads);
  engine_.apply(atom->f, atom->torque); // the recipients set on the threads, above
  // Each atom's own term, on the rank that owns it (its recipient side): a pair across ranks
  // counts once in the sum over ranks, each of its atoms where it lives.
  if (virial_wanted)
    engine_.add_virial(vflag_global ? virial : nullptr, vflag_atom ? vatom : nullptr);
  publish_contacts();
  tri::InteractionTally tally = engine_.tally();
  tally.add_passed(static_cast<long long>(passed_.size())); // as their apart_result would
  board.publish(board_slot_, tally, summary.first);
  board.publish_deepest(board_slot_, summary.deepest);
  board.publish_fastest_pair(summary.fastest);
  board.publish_particle_pairs(list);
}

void PairTriGran::StepSummary::merge(const StepSummary &later) {
  first.merge(later.first);
  deepest.merge(later.deepest);
  fastest.merge(later.fastest);
}

// Tasks [first_task, last_task) in the listing's order, each after the pairs passed over before
// it; with `trailing`, the pairs passed over after the last task as well.
PairTriGran::StepSummary PairTriGran::summarize_tasks(std::size_t first_task,
                                                      std::size_t last_task, bool trailing) const {
  const tagint *tag = atom->tag;
  StepSummary s;
  std::size_t passed =
      static_cast<std::size_t>(std::lower_bound(passed_.begin(), passed_.end(), first_task,
                                                [](const PassedPair &p, std::size_t k) {
                                                  return p.before < k;
                                                }) -
                               passed_.begin());
  auto consider_passed_before = [&](std::size_t k) {
    for (; passed < passed_.size() && passed_[passed].before <= k; ++passed)
      s.fastest.consider(passed_[passed].geometry, passed_[passed].tag_i, passed_[passed].tag_j);
  };
  for (std::size_t k = first_task; k < last_task; ++k) {
    consider_passed_before(k);
    const Task &t = tasks_[k];
    const tri::PairForceResult &r = engine_.result(k);
    const long a = std::min(tag[t.i], tag[t.j]), b = std::max(tag[t.i], tag[t.j]);
    s.fastest.consider(task_geometry_[k], tag[t.i], tag[t.j]);
    if (r.intersecting && !s.first.found())
      s.first = {a, b};
    s.deepest.consider(r, a, b);
  }
  if (trailing)
    consider_passed_before(std::numeric_limits<std::size_t>::max());
  return s;
}

// The step's run-safety summary: the fastest approaching pair, the first intersecting one and
// the deepest contact, each the first extreme in the listing's order. Blocks of kSummaryTasks
// tasks on the engine's threads, merged in order: the same on any thread count.
PairTriGran::StepSummary PairTriGran::summarize(int threads) {
  const std::size_t n = tasks_.size();
  const std::size_t blocks = std::max<std::size_t>(1, (n + kSummaryTasks - 1) / kSummaryTasks);
  summaries_.resize(blocks);
  const long count = static_cast<long>(blocks);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1 && count > 1)
  for (long b = 0; b < count; ++b) {
    const std::size_t first = static_cast<std::size_t>(b) * kSummaryTasks;
    summaries_[static_cast<std::size_t>(b)] =
        summarize_tasks(first, std::min(n, first + kSummaryTasks), b == count - 1);
  }
  StepSummary out = summaries_[0];
  for (std::size_t b = 1; b < blocks; ++b)
    out.merge(summaries_[b]);
  return out;
}

void PairTriGran::publish_contacts() {
  tri_liggghts::ContactBoard &board = particles_->board();
  if (!board.contacts_wanted())
    return;
  contact_rows_.clear();
  for (std::size_t k = 0; k < tasks_.size(); ++k) {
    const TaskView v = view(tasks_[k]);
    bool first = true;
    for (const tri::ContactRecord &rec : engine_.records(k)) {
      contact_rows_.push_back({v.a, v.b, -1, -1, k, first, rec});
      first = false;
    }
  }
  board.publish_contacts(board_slot_, contact_rows_);
}

// Every rank that failed stops (error->one): the others may have no failing pair.
void PairTriGran::report_failure() {
  const Task &t = tasks_[engine_.failed_task()];
  const std::string msg = std::string(kStyle) + ": the contact kernel failed on particles " +
                          std::to_string(atom->tag[t.i]) + " and " +
                          std::to_string(atom->tag[t.j]) + ": " + engine_.failure();
  error->one(FLERR, msg.c_str());
}

double PairTriGran::memory_usage() {
  return PairGran::memory_usage() + static_cast<double>(engine_.bytes()) +
         static_cast<double>(candidates_.bytes()) +
         static_cast<double>(tasks_.capacity() * sizeof(Task)) +
         static_cast<double>(passed_.capacity() * sizeof(PassedPair) + travel_.bytes());
}
