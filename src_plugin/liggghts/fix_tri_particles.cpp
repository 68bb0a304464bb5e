#include "fix_tri_particles.h"

#include "interaction/interaction_engine.h"

#include "incompatible_styles.h"
#include "particle_insertion.h"
#include "particle_options.h"
#include "shape_builder.h"

#include "body/rigid_body.h"
#include "body/shape_error.h"
#include "geometry/seeded_random.h"

#include "peratom_restart.h"
#include "restart_shapes.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "output.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

#include <mpi.h>
#include <omp.h>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

// state_ columns
constexpr int kShape = 0, kQuat = FixTriParticles::kQuatColumn;
// pending_ columns
constexpr int kForce = 0, kTorque = 3, kFlag = 6;
constexpr double kUnset = -1.0; // shape by the assign rule once the atom has a tag
// -2 - s: inserted by a template with shape s, initialised once the atom has a tag
double inserted_with(int s) { return -2.0 - s; }

} // namespace

FixTriParticles::FixTriParticles(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "Fix tri/particles requires atom_style sphere (per-atom radius, rmass, "
                      "omega and torque)");
  if (!atom->tag_enable)
    error->all(FLERR, "Fix tri/particles requires atom IDs (atom_modify id yes)");
  if (igroup != group->find("all"))
    error->all(FLERR, "Fix tri/particles must be applied to group all: every atom is a "
                      "triangulated particle");
  // LIGGGHTS replaces a fix defined again under its ID: it deletes the old one and leaves its
  // slot empty while this one is built. The particles' shapes, orientations and angular
  // momenta would go with it.
  for (int k = 0; k < modify->nfix; ++k) {
    if (!modify->fix[k])
      error->all(FLERR, "Fix tri/particles cannot be defined again: the particles' shapes, "
                        "orientations and angular momenta belong to its first definition");
    if (std::strcmp(modify->fix[k]->style, "tri/particles") == 0)
      error->all(FLERR, "Only one fix tri/particles may be defined");
  }

  const tri_liggghts::ParticleOptions opt = tri_liggghts::parse_particle_options(narg, arg, 3, error);
  density_ = opt.density;
  epsilon_ = opt.epsilon;
  epsilon_auto_ = opt.epsilon_auto;
  layer_inside_ = opt.layer_inside;
  check_timestep_every_ = opt.check_timestep_every;
  assign_by_type_ = opt.assign_by_type;
  assign_seed_ = opt.assign_seed;
  orient_random_ = opt.orient_random;
  orient_seed_ = opt.orient_seed;
  orient_file_ = opt.orient_file;
  templates_ = opt.templates;

  shapes_ = tri_liggghts::build_shapes(lmp, opt);
  if (!epsilon_auto_) {
    set_soft_layers();
    tri_liggghts::check_shapes_against_epsilon(lmp, shapes_, epsilon_);
  }
  monitor_ = std::make_unique<tri_liggghts::RunSafetyMonitor>(lmp, epsilon_);

  peratom_flag = 1;
  size_peratom_cols = kValues;
  peratom_freq = 1;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  comm_forward = 5; // shape + quaternion (the shape of atoms initialised in this pre_force)
  comm_border = 5;  // shape + quaternion

  grow_arrays(atom->nmax);
  atom->add_callback(0);
  atom->add_callback(1);
  atom->add_callback(2);

  for (int i = 0; i < atom->nlocal; ++i) {
    initialise_atom(i);
    apply_mass_and_radius(i);
  }
  // Templates defined before this fix get their shapes now (later ones in their constructor).
  tri_liggghts::bind_templates(lmp, *this);
}

FixTriParticles::~FixTriParticles() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  atom->delete_callback(id, 2);
  memory->destroy(state_);
  memory->destroy(pending_);
}

int FixTriParticles::setmask() { return PRE_FORCE | POST_FORCE | END_OF_STEP; }

void FixTriParticles::post_force(int) { monitor_->after_pair_forces(board_); }

// After every fix tri/wall has added its forces.
void FixTriParticles::end_of_step() {
  monitor_->end_of_step(board_);
  if (check_timestep_every_ > 0 && update->ntimestep % check_timestep_every_ == 0)
    tri_liggghts::check_timestep(lmp, board_, type_bodies(), epsilon_, default_wall_layer(), false);
  if (output->restart_requested(update->ntimestep)) // a restart file is written this step
    bring_contact_history_up_to_date();
}

// LIGGGHTS keeps pair tri/gran's contact history in the neighbour list between neighbour
// builds and copies it to the atoms (which a restart file stores) only before each build and
// in write_restart. A restart file written during a run (`restart N`) would get the history of
// the last build; copying it here, after this step's forces and before the file is written,
// makes the run that reads the file continue this one bit for bit. (LIGGGHTS's pair gran has the
// same gap with spheres.)
void FixTriParticles::bring_contact_history_up_to_date() {
  for (int k = 0; k < modify->nfix; ++k)
    if (std::strcmp(modify->fix[k]->style, "contacthistory") == 0)
      modify->fix[k]->setup_pre_exchange(); // copies only if the pair ran since the last copy
}

// A source removed between runs (unfix, another pair_style) leaves nothing behind; the
// sources of the next run join again in their init(), unless it runs with `pre no`.
void FixTriParticles::post_run() {
  board_.end_run();
  initialised_since_run_ = false;
}

void FixTriParticles::initialise_atom(int i, int shape) {
  const auto tag = static_cast<std::uint64_t>(atom->tag[i]);
  int s = shape;
  if (s < 0)
    s = assign_by_type_    ? atom->type[i] - 1
        : num_shapes() > 1 ? tri::seeded_index(assign_seed_, tag, num_shapes())
                           : 0;
  state_[i][kShape] = s;
  const Eigen::Quaterniond q = orient_random_ ? tri::random_orientation(orient_seed_, tag)
                               : orient_file_ ? shapes_[s].input_orientation
                                              : Eigen::Quaterniond::Identity();
  set_orientation(i, q);
  set_angular_momentum(i, Eigen::Vector3d::Zero());
  std::fill(pending_[i], pending_[i] + kPending, 0.0);
}

int FixTriParticles::initialise_unset_atoms() {
  int count = 0;
  for (int i = 0; i < atom->nlocal; ++i)
    if (state_[i][kShape] < 0.0) {
      if (atom->tag[i] <= 0)
        error->one(FLERR, "Fix tri/particles: an atom without an ID cannot be given a shape");
      const double mark = state_[i][kShape];
      initialise_atom(i, mark == kUnset ? -1 : static_cast<int>(-2.0 - mark));
      apply_mass_and_radius(i);
      // A spin given on insertion (fix insert/* `omega`) is the particle's.
      const Eigen::Vector3d w(atom->omega[i][0], atom->omega[i][1], atom->omega[i][2]);
      if (w != Eigen::Vector3d::Zero())
        set_angular_momentum(i, tri::angmom_from_omega(orientation(i), w, principal_inertia(i)));
      ++count;
    }
  return count;
}

void FixTriParticles::set_inserted_shape(int i, int shape) {
  if (i >= 0 && i < atom->nlocal && shape >= 0 && shape < num_shapes() && state_[i][kShape] < 0.0)
    state_[i][kShape] = inserted_with(shape);
}

void FixTriParticles::apply_mass_and_radius(int i) {
  const tri::Shape &s = shapes_[shape_index(i)];
  atom->radius[i] = tri::contact_reach(s, epsilon_);
  atom->rmass[i] = density_ * s.volume;
  if (atom->density_flag)
    atom->density[i] = density_;
}

void FixTriParticles::init() {
  initialised_since_run_ = true;
  tri_liggghts::check_insertion(lmp, *this); // names the distribution of a refused template
  tri_liggghts::refuse_incompatible_styles(lmp, id);
  tri_liggghts::mend_output_frequencies(lmp);
  warn_of_changed_radii();
  initialise_unset_atoms();
  for (int i = 0; i < atom->nlocal; ++i)
    apply_mass_and_radius(i);
}

// `set diameter|mass|density`, read_dump's radius and the like change what this fix owns; the
// next run resets it, and says so rather than run silently on other values than the deck gave.
void FixTriParticles::warn_of_changed_radii() {
  long changed = 0;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (state_[i][kShape] == kUnset)
      continue;
    const tri::Shape &s = shapes_[shape_index(i)];
    changed += atom->radius[i] != tri::contact_reach(s, epsilon_) ||
               atom->rmass[i] != density_ * s.volume;
  }
  long total = 0;
  MPI_Allreduce(&changed, &total, 1, MPI_LONG, MPI_SUM, world);
  if (total > 0 && comm->me == 0) {
    const std::string msg =
        "Fix tri/particles: " + std::to_string(total) +
        " particle(s) had their radius or mass changed since the last run (set diameter, mass "
        "or density, read_dump, ...): reset to their shape's contact reach and mass";
    error->warning(FLERR, msg.c_str());
  }
}

// Once, at the first run: how the work is shared, since OMP_NUM_THREADS unset no longer means
// every core per rank (src_plugin/driver/thread_default.h).
void FixTriParticles::report_parallelism() const {
  if (comm->me != 0)
    return;
  char line[256];
  std::snprintf(line, sizeof line, "tri/particles: %d MPI rank(s), %d OpenMP thread(s) each%s",
                comm->nprocs, omp_get_max_threads(),
                std::getenv("OMP_NUM_THREADS") ? ""
                                               : " (OMP_NUM_THREADS unset: a node's cores "
                                                 "shared among its ranks)");
  if (screen)
    std::fprintf(screen, "%s\n", line);
  if (logfile)
    std::fprintf(logfile, "%s\n", line);
}

void FixTriParticles::setup_pre_force(int) {
  if (!run_started_)
    report_parallelism();
  run_started_ = true;
  monitor_->new_run();
  if (epsilon_auto_ && !epsilon_resolved_)
    error->all(FLERR, "Fix tri/particles: 'epsilon' is required here: 'epsilon auto' (the "
                      "default) sizes the soft layer from the contact material, and no pair "
                      "tri/gran or fix tri/wall published one for the particles present");
  pre_force(0);
}

// After the setup force evaluation: the time-step check sees the published neighbour list.
void FixTriParticles::setup(int) {
  if (check_timestep_every_ >= 0)
    tri_liggghts::check_timestep(lmp, board_, type_bodies(), epsilon_, default_wall_layer(), true);
}

tri_liggghts::TypeBodies FixTriParticles::type_bodies() const {
  return tri_liggghts::type_bodies(lmp, shapes_, density_, assign_by_type_);
}

void FixTriParticles::resolve_epsilon() {
  // With the layer inside, the radii do not depend on epsilon, so a source that publishes
  // after the first (fix tri/wall initialises after pair tri/gran) may still widen it: the
  // layer then covers every contact, walls included. With the layer outside, the pair has
  // sized its cutoffs from the radii of the first choice.
  const bool may_widen = layer_inside_ && !run_started_;
  if (!epsilon_auto_ || (epsilon_resolved_ && !may_widen))
    return;
  const tri_liggghts::AutoEpsilon chosen =
      tri_liggghts::choose_auto_epsilon(lmp, board_, type_bodies());
  if (!chosen.found || (epsilon_resolved_ && !(chosen.epsilon > epsilon_)))
    return;
  char line[600];
  std::snprintf(line, sizeof line,
                "tri/particles: epsilon auto = %g m (peak overlap v sqrt(meff / kn) of a "
                "head-on contact at the characteristic velocity %g m/s: %s, types %d and %d%s, "
                "meff %g kg, kn %g N/m, gives %g m = %g of the two soft layers)\n",
                chosen.epsilon, chosen.speed, chosen.source.c_str(), chosen.itype, chosen.jtype,
                chosen.wall ? " (wall)" : "", chosen.meff, chosen.kn, chosen.overlap,
                tri::kAutoEpsilonFraction);
  adopt_epsilon(chosen.epsilon, line);
}

void FixTriParticles::adopt_epsilon(double epsilon, const char *line) {
  epsilon_ = epsilon;
  epsilon_resolved_ = true;
  monitor_->set_epsilon(epsilon_);
  set_soft_layers();
  tri_liggghts::check_shapes_against_epsilon(lmp, shapes_, epsilon_);
  for (int i = 0; i < atom->nlocal; ++i)
    if (state_[i][kShape] != kUnset)
      apply_mass_and_radius(i);
  if (comm->me == 0) {
    if (screen)
      std::fputs(line, screen);
    if (logfile)
      std::fputs(line, logfile);
  }
}

void FixTriParticles::set_soft_layers() {
  try {
    for (tri::Shape &s : shapes_)
      s = tri::with_soft_layer(std::move(s), layer_inside_ ? epsilon_ : 0.0);
  } catch (const tri::ShapeError &e) {
    const std::string msg = std::string("Fix tri/particles: ") + e.what() +
                            " (or 'layer outside': the soft layer outside the mesh)";
    error->all(FLERR, msg.c_str());
  }
}

void FixTriParticles::given_surface(int i, tri::TriangleSoA &out) const {
  const double *x = atom->x[i];
  tri::transform_soa(shapes_[shape_index(i)].surface, orientation(i).toRotationMatrix(),
                     Eigen::Vector3d(x[0], x[1], x[2]), out);
}

void FixTriParticles::rejoin_after_run_pre_no() {
  // Only inside a run: between runs (a variable read by print) the next run's init decides.
  if (!initialised_since_run_ && update->whichflag != 0) {
    board_.restore_membership();
    initialised_since_run_ = true;
  }
}

void FixTriParticles::pre_force(int) {
  rejoin_after_run_pre_no();
  // Atoms inserted during a run (fix insert/pour) arrive unset; their tags exist by now.
  initialise_unset_atoms();
  comm->forward_comm_fix(this);
  // A new force evaluation: world-frame triangles are built when a source asks for them.
  size_world(static_cast<std::size_t>(atom->nlocal + atom->nghost));
  ++evaluation_;
  board_.clear_tallies(); // this force evaluation's sources publish next
}

void FixTriParticles::build_body(int i) {
  const int s = shape_index(i);
  if (s < 0)
    return;
  double **x = atom->x;
  const tri::Shape &shape = shapes_[s];
  tri::Body &b = bodies_[i];
  b.triangles = &world_[i];
  b.frame = &shape.soa;
  b.epsilon = epsilon_;
  b.longest_edge = shape.max_edge_length;
  b.min_edge = shape.min_edge_length;
  b.thinnest = shape.thinnest_extent;
  b.edge_bulge = shape.edge_bulge.empty() ? nullptr : shape.edge_bulge.data();
  b.lift = shape.surface_lift;
  b.spheres = shape.corner_spheres.empty() ? nullptr : shape.corner_spheres.data();
  b.ball_lift = shape.ball_lift;
  b.convex = shape.convex;
  b.state.x = Eigen::Vector3d(x[i][0], x[i][1], x[i][2]);
  b.state.v = Eigen::Vector3d(atom->v[i][0], atom->v[i][1], atom->v[i][2]);
  b.state.omega = Eigen::Vector3d(atom->omega[i][0], atom->omega[i][1], atom->omega[i][2]);
  b.state.mass = atom->rmass[i];
  b.pose.x = b.state.x;
  b.pose.q = orientation(i);
  b.pose.radius = shape.bounding_radius;
  b.pose.frame = &shape.soa;
}

void FixTriParticles::transform_atom(int i) {
  const int s = shape_index(i);
  if (s < 0)
    return;
  ensure_body_of(i);
  place_triangles(s, bodies_[i], world_[i]);
}

void FixTriParticles::place_triangles(int s, const tri::Body &b, tri::TriangleSoA &out) const {
  tri::transform_soa(shapes_[s].soa, b.pose.q.toRotationMatrix(), b.pose.x, out);
}

void FixTriParticles::size_world(std::size_t n) {
  if (world_stamp_.size() < n) {
    world_stamp_.resize(n, 0);
    body_stamp_.resize(n, 0);
  }
  if (world_.size() >= n)
    return;
  world_.resize(n);
  bodies_.resize(n);
  for (std::size_t k = 0; k < n; ++k) // the triangles may have moved
    bodies_[k].triangles = &world_[k];
}

void FixTriParticles::prepare_bodies() {
  size_world(static_cast<std::size_t>(atom->nlocal + atom->nghost));
}

template <class Work> void FixTriParticles::once_this_evaluation(long long *stamp, Work work) {
  // GCC's atomic builtins on the plain stamp (C++17 has no atomic_ref): every other access to
  // the stamps is outside parallel regions.
  for (int spins = 0;; ++spins) {
    long long seen = __atomic_load_n(stamp, __ATOMIC_ACQUIRE);
    if (seen == evaluation_)
      return;
    if (seen == -evaluation_) { // another thread's, ~0.1 us; unless the host has more threads
      if (spins < 4096)         // than cores and that one was descheduled: then give way
        __builtin_ia32_pause();
      else
        std::this_thread::yield();
      continue;
    }
    if (!__atomic_compare_exchange_n(stamp, &seen, -evaluation_, false, __ATOMIC_ACQ_REL,
                                     __ATOMIC_ACQUIRE))
      continue;
    try {
      work();
    } catch (...) { // (no memory) unclaimed again: a waiting task claims it, none waits for ever
      __atomic_store_n(stamp, 0LL, __ATOMIC_RELEASE);
      throw;
    }
    __atomic_store_n(stamp, evaluation_, __ATOMIC_RELEASE);
    return;
  }
}

void FixTriParticles::ensure_body_of(int i) {
  once_this_evaluation(&body_stamp_[i], [&] { build_body(i); });
}

void FixTriParticles::ensure_world_triangles_of(int i) {
  once_this_evaluation(&world_stamp_[i], [&] { transform_atom(i); });
}

void FixTriParticles::prepare_task_bodies(int threads) {
  prepare_bodies();
  if (static_cast<int>(task_caches_.size()) < threads)
    task_caches_.resize(static_cast<std::size_t>(threads));
}

tri_liggghts::TaskPins FixTriParticles::reserve_pins(std::size_t tasks, int threads) {
  tri_liggghts::TaskPins pins;
  pins.first = next_pin_;
  pins.group_tasks = tri::InteractionEngine::tasks_per_group(static_cast<long>(tasks), threads);
  next_pin_ += static_cast<long long>(tasks) / pins.group_tasks + 1;
  return pins;
}

const tri::Body &FixTriParticles::task_body(int i, int thread, long long pin) {
  ensure_body_of(i);
  const int s = shape_index(i);
  tri_liggghts::WorldCache &cache = task_caches_[static_cast<std::size_t>(thread)];
  const tri_liggghts::WorldCache::Found found = s < 0 ? tri_liggghts::WorldCache::Found{}
                                                      : cache.find(i, evaluation_, pin);
  if (found.slot < 0) {
    ensure_world_triangles_of(i);
    return bodies_[i];
  }
  tri::Body &b = cache.body(found.slot);
  if (found.fill) {
    b = bodies_[i];
    place_triangles(s, b, cache.triangles(found.slot));
    b.triangles = &cache.triangles(found.slot);
  }
  return b;
}

void FixTriParticles::update_world_triangles(int n) {
  prepare_bodies();
  for (int i = 0; i < n; ++i)
    ensure_world_triangles_of(i);
}

/* ---------------- per-atom storage: the LIGGGHTS callbacks ---------------- */

void FixTriParticles::grow_arrays(int nmax) {
  memory->grow(state_, nmax, kValues, "tri/particles:state");
  memory->grow(pending_, nmax, kPending, "tri/particles:pending");
  array_atom = state_;
}

void FixTriParticles::copy_arrays(int i, int j, int) {
  std::memcpy(state_[j], state_[i], kValues * sizeof(double));
  std::memcpy(pending_[j], pending_[i], kPending * sizeof(double));
}

void FixTriParticles::set_arrays(int i) {
  // create_atoms calls this before it assigns tags; such atoms are marked and initialised
  // from their tag in init() or pre_force(). With a tag, the result is the same function of
  // (tag, seeds) as in the constructor, so a repeated call changes nothing.
  if (atom->tag[i] > 0) {
    initialise_atom(i);
    apply_mass_and_radius(i);
    return;
  }
  state_[i][kShape] = kUnset;
  set_orientation(i, Eigen::Quaterniond::Identity());
  set_angular_momentum(i, Eigen::Vector3d::Zero());
  std::fill(pending_[i], pending_[i] + kPending, 0.0);
}

int FixTriParticles::pack_exchange(int i, double *buf) {
  std::memcpy(buf, state_[i], kValues * sizeof(double));
  std::memcpy(buf + kValues, pending_[i], kPending * sizeof(double));
  return kValues + kPending;
}

int FixTriParticles::unpack_exchange(int nlocal, double *buf) {
  std::memcpy(state_[nlocal], buf, kValues * sizeof(double));
  std::memcpy(pending_[nlocal], buf + kValues, kPending * sizeof(double));
  any_pending_ = any_pending_ || pending_[nlocal][kFlag] == 1.0;
  return kValues + kPending;
}

int FixTriParticles::pack_border(int n, int *list, double *buf) {
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const double *s = state_[list[k]];
    for (int v = 0; v < 5; ++v)
      buf[m++] = s[v];
  }
  return m; // LIGGGHTS: pack_border returns the total, pack_comm the count per atom
}

int FixTriParticles::unpack_border(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; ++i)
    for (int v = 0; v < 5; ++v)
      state_[i][v] = buf[m++];
  return m;
}

int FixTriParticles::pack_comm(int n, int *list, double *buf, int, int *) {
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const double *s = state_[list[k]];
    for (int v = 0; v < 5; ++v)
      buf[m++] = s[v];
  }
  return 5; // LIGGGHTS 3.8: values per atom, the caller multiplies
}

void FixTriParticles::unpack_comm(int n, int first, double *buf) {
  int m = 0;
  for (int i = first; i < first + n; ++i)
    for (int v = 0; v < 5; ++v)
      state_[i][v] = buf[m++];
}

int FixTriParticles::pack_restart(int i, double *buf) {
  buf[0] = kValues + kPending + 1;
  std::memcpy(buf + 1, state_[i], kValues * sizeof(double));
  double *pending = buf + 1 + kValues;
  for (int k = 0; k < 3; ++k) {
    pending[kForce + k] = atom->f[i][k];
    pending[kTorque + k] = atom->torque[i][k];
  }
  pending[kFlag] = 1.0;
  return kValues + kPending + 1;
}

void FixTriParticles::unpack_restart(int nlocal, int nth) {
  const double *record = tri_liggghts::restart_record(atom->extra, nlocal, nth);
  std::memcpy(state_[nlocal], record, kValues * sizeof(double));
  std::memcpy(pending_[nlocal], record + kValues, kPending * sizeof(double));
  any_pending_ = any_pending_ || pending_[nlocal][kFlag] == 1.0;
}

int FixTriParticles::size_restart(int) { return kValues + kPending + 1; }
int FixTriParticles::maxsize_restart() { return kValues + kPending + 1; }

bool FixTriParticles::take_restored_force_and_torque(int i, double *f, double *torque) {
  double *s = pending_[i];
  if (s[kFlag] != 1.0)
    return false;
  for (int k = 0; k < 3; ++k) {
    f[k] = s[kForce + k];
    torque[k] = s[kTorque + k];
  }
  s[kFlag] = 0.0;
  return true;
}

void FixTriParticles::take_restored_forces_and_torques(int groupbit) {
  if (!any_pending_)
    return;
  any_pending_ = false;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (atom->mask[i] & groupbit)
      take_restored_force_and_torque(i, atom->f[i], atom->torque[i]);
    any_pending_ = any_pending_ || pending_[i][kFlag] == 1.0; // outside the group: kept
  }
}

// The shapes themselves are rebuilt from the deck; the restart file keeps what the deck must
// repeat (restart_shapes.h), and a deck that differs is refused, naming each difference.
void FixTriParticles::write_restart(FILE *fp) {
  if (comm->me != 0)
    return;
  const std::vector<char> data =
      tri_liggghts::encode(tri_liggghts::make_record(shapes_, epsilon_, density_, layer_inside_));
  const int size = static_cast<int>(data.size());
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(data.data(), 1, data.size(), fp);
}

void FixTriParticles::restart(char *buf) {
  monitor_->skip_initial_check();
  std::string msg;
  tri_liggghts::ParticlesRecord file;
  try {
    file = tri_liggghts::decode(buf);
    // `epsilon auto` is not resolved yet (no material has been published): the run goes on
    // with the layer it had, and the rest of the deck must match.
    const bool inherit = epsilon_auto_ && !epsilon_resolved_;
    const std::string d = tri_liggghts::differences(
        file, tri_liggghts::make_record(shapes_, inherit ? file.epsilon : epsilon_, density_,
                                        layer_inside_));
    if (!d.empty())
      msg = "Fix tri/particles: this deck differs from the run that wrote the restart file: " + d;
  } catch (const std::runtime_error &e) {
    msg = std::string("Fix tri/particles: ") + e.what();
  }
  if (!msg.empty())
    error->all(FLERR, msg.c_str());
  if (epsilon_auto_ && !epsilon_resolved_) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "tri/particles: epsilon auto = %g m, as in the restart file\n", file.epsilon);
    adopt_epsilon(file.epsilon, line);
    run_started_ = true; // fixed: the materials of this deck do not widen it
  }
}

double FixTriParticles::max_rad(int type) {
  double r = 0.0;
  if (assign_by_type_) {
    if (type >= 1 && type <= num_shapes())
      r = reach(type - 1);
  } else {
    for (int s = 0; s < num_shapes(); ++s)
      r = std::max(r, reach(s));
  }
  return r;
}

double FixTriParticles::memory_usage() {
  double bytes = static_cast<double>(atom->nmax) * (kValues + kPending) * sizeof(double);
  for (const tri::TriangleSoA &w : world_)
    bytes += 3.0 * w.x.capacity() * sizeof(double) + sizeof(w);
  for (const tri_liggghts::WorldCache &c : task_caches_)
    bytes += static_cast<double>(c.bytes());
  bytes += static_cast<double>(bodies_.capacity() * sizeof(tri::Body) +
                               (world_stamp_.capacity() + body_stamp_.capacity()) *
                                   sizeof(long long));
  return bytes;
}
