#include "fix_tri_wall.h"

#include "fix_tri_particles.h"
#include "incompatible_styles.h"

#include "body/rigid_motion.h"
#include "peratom_restart.h"

#include "atom.h"
#include "error.h"
#include "fix_mesh_surface.h"
#include "fix_neighlist_mesh.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "tri_mesh.h"
#include "update.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <omp.h>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
const char *kStyle = "Fix tri/wall";
}

FixTriWall::FixTriWall(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg) {
  settings_.interaction.coefficients.limit_force = true; // repulsive only, as pair tri/gran
  // The wall's forces on the particles count in the pressure and stress/atom (LIGGGHTS 3.8 adds
  // every fix's virial that sets this flag; keyword `virial no` leaves it out).
  virial_flag = 1;
  int i = 3;
  while (i < narg) {
    const std::string key = arg[i];
    if (key == "mesh") {
      ++i;
      while (i < narg && modify->find_fix_id(arg[i]) != nullptr)
        mesh_ids_.push_back(arg[i++]);
      if (mesh_ids_.empty()) {
        const std::string msg = std::string(kStyle) + ": 'mesh' must name at least one fix " +
                                "mesh/surface, got '" + (i < narg ? arg[i] : "") + "'";
        error->all(FLERR, msg.c_str());
      }
    } else if (key == "epsilon") {
      if (i + 1 >= narg)
        error->all(FLERR, "Fix tri/wall: missing value after 'epsilon'");
      char *end = nullptr;
      epsilon_ = std::strtod(arg[i + 1], &end);
      if (*end != '\0' || !(epsilon_ > 0.0)) {
        const std::string msg = std::string(kStyle) + ": 'epsilon' must be > 0, got '" +
                                arg[i + 1] + "'";
        error->all(FLERR, msg.c_str());
      }
      i += 2;
    } else if (key == "virial") {
      const std::string value = i + 1 < narg ? arg[i + 1] : "";
      if (value != "yes" && value != "no") {
        const std::string msg =
            std::string(kStyle) + ": 'virial' must be yes or no, got '" + value + "'";
        error->all(FLERR, msg.c_str());
      }
      virial_flag = value == "yes";
      i += 2;
    } else if (!tri_liggghts::parse_contact_keyword(narg, arg, &i, settings_, kStyle, error)) {
      std::string msg = tri_liggghts::gran_submodel_message(kStyle, arg[i],
                                                            i + 1 < narg ? arg[i + 1] : nullptr);
      if (msg.empty())
        msg = std::string(kStyle) + ": unknown keyword '" + key + "'";
      error->all(FLERR, msg.c_str());
    }
  }
  if (mesh_ids_.empty())
    error->all(FLERR, "Fix tri/wall needs 'mesh MESH_ID ...'");
  for (const std::string &id : mesh_ids_) {
    auto *mesh = dynamic_cast<FixMeshSurface *>(modify->find_fix_id(id.c_str()));
    if (!mesh) {
      const std::string msg = std::string(kStyle) + ": fix '" + id + "' is not a fix mesh/surface";
      error->all(FLERR, msg.c_str());
    }
    meshes_.push_back(mesh);
  }

  // Per mesh: the tangential history, then (after every mesh's history) the separating axis.
  values_per_atom_ = static_cast<int>(meshes_.size()) * (tri::kHistoryDoubles + 3);
  values_without_kept_ = values_per_atom_;
  if (settings_.interaction.kept_tolerance > 0.0)
    values_per_atom_ += static_cast<int>(meshes_.size()) * tri::kKeptContactDoubles;
  restart_peratom = 1;
  scalar_flag = 1;
  extscalar = 0;
  global_freq = 1;
  grow_arrays(atom->nmax);
  for (int k = 0; k < atom->nmax; ++k)
    std::fill(history_[k], history_[k] + values_per_atom_, 0.0);
  atom->add_callback(0);
  atom->add_callback(1);
}

FixTriWall::~FixTriWall() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(history_);
}

int FixTriWall::setmask() { return POST_FORCE; }

void FixTriWall::post_create() {
  for (FixMeshSurface *mesh : meshes_)
    mesh->createWallNeighList(groupbit);
}

void FixTriWall::init() {
  particles_ = static_cast<FixTriParticles *>(modify->find_fix_style("tri/particles", 0));
  if (!particles_)
    error->all(FLERR, "Fix tri/wall requires fix tri/particles (define it before the run)");
  // The meshes' neighbour lists were made for this fix when it was created (post_create); a
  // mesh defined again since (possibly at the old address) has none.
  for (std::size_t m = 0; m < meshes_.size(); ++m)
    if (modify->find_fix_id(mesh_ids_[m].c_str()) != meshes_[m] ||
        !meshes_[m]->hasNeighList()) {
      const std::string msg = std::string(kStyle) + " " + id + ": mesh '" + mesh_ids_[m] +
                              "' was removed or defined again after this fix (unfix the wall "
                              "too, and define it again after the mesh)";
      error->all(FLERR, msg.c_str());
    }
  // Material of (particle type, wall type): LIGGGHTS sizes the property tables by the
  // largest type of atoms and meshes alike.
  int ntypes = atom->ntypes;
  std::vector<int> wall_types;
  for (FixMeshSurface *mesh : meshes_) {
    ntypes = std::max(ntypes, mesh->atomTypeWall());
    wall_types.push_back(mesh->atomTypeWall());
  }
  materials_.load(lmp, ntypes, settings_.interaction, settings_.model,
                  particles_->type_bodies().sphere, true, "fix tri/wall");
  loaded_.clear();
  for (FixMeshSurface *mesh : meshes_)
    loaded_.push_back(mesh->trackStress());
  board_slot_ = particles_->board().join(id, tri_liggghts::SourceKind::walls);
  tri_liggghts::MaterialHint hint = materials_.hint(atom->ntypes, wall_types);
  hint.wall_epsilon = epsilon_; // < 0: the particles' default for walls
  particles_->board().publish_material(board_slot_, hint);
  particles_->resolve_epsilon(); // `epsilon auto` without pair tri/gran: from this wall
  layer_ = epsilon_ >= 0.0 ? epsilon_ : particles_->default_wall_layer();
  // The mesh neighbour list finds triangles within radius (the particle's contact reach) times
  // LIGGGHTS's contact distance factor; widen it by the wall's layer.
  double rmin = std::numeric_limits<double>::infinity();
  for (int s = 0; s < particles_->num_shapes(); ++s)
    rmin = std::min(rmin, particles_->reach(s));
  neighbor->register_contact_dist_factor(1.0 + layer_ / rmin);
}

void FixTriWall::setup(int vflag) { compute(false, vflag); }

void FixTriWall::post_force(int vflag) { compute(true, vflag); }

// The step's tasks: mesh by mesh, the particles near it in atom order. Each mesh's contact
// lists are turned into per-particle triangle lists on one thread; the particles are then
// shared out in contiguous runs, each thread counting its tasks, then writing them at offsets
// that give the serial order. A task's kept candidates are asked for by the thread that owns
// its particle, in slot order (candidate_store.h), so each key gets the entry it would serially.
void FixTriWall::collect_tasks() {
  const int nlocal = atom->nlocal;
  const std::size_t nmesh = meshes_.size();
  if (near_.size() < nmesh * static_cast<std::size_t>(nlocal))
    near_.resize(nmesh * static_cast<std::size_t>(nlocal));
  for (std::size_t m = 0; m < nmesh; ++m)
    list_near_triangles(static_cast<int>(m));
  const int threads = tri_liggghts::pair_loop_threads(settings_.loop, nmesh * nlocal);
  thread_tasks_.assign(nmesh * static_cast<std::size_t>(threads), 0);
  if (threads <= 1) {
    count_tasks(0, 0, nlocal);
    begin_listing(1);
    write_tasks(0, 0, nlocal);
  } else {
#pragma omp parallel num_threads(threads)
    {
      const int t = omp_get_thread_num();
      const int first = static_cast<int>(static_cast<long>(nlocal) * t / threads);
      const int last = static_cast<int>(static_cast<long>(nlocal) * (t + 1) / threads);
      count_tasks(t, first, last);
#pragma omp barrier
#pragma omp single
      begin_listing(threads);
      write_tasks(t, first, last);
    }
  }
  candidates_.end_step();
}

// near_[m * nlocal + a]: mesh m's triangles within the contact lists of particle a, (global id,
// mesh-local index). Left empty for particles outside the group; write_tasks empties them again.
void FixTriWall::list_near_triangles(int m) {
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  std::vector<std::pair<int, int>> *near = near_.data() + static_cast<std::size_t>(m) * nlocal;
  TriMesh *mesh = meshes_[m]->triMesh();
  FixNeighlistMesh *list = meshes_[m]->meshNeighlist();
  const int ntri = mesh->sizeLocal() + mesh->sizeGhost();
  for (int t = 0; t < ntri; ++t)
    for (int a : list->get_contact_list(t))
      if (a < nlocal && (mask[a] & groupbit))
        near[a].emplace_back(mesh->id(t), t);
}

// How many tasks particles [first, last) give, per mesh: thread_tasks_[thread * meshes + m].
void FixTriWall::count_tasks(int thread, int first, int last) {
  const std::size_t nmesh = meshes_.size();
  const std::size_t nlocal = static_cast<std::size_t>(atom->nlocal);
  for (std::size_t m = 0; m < nmesh; ++m) {
    std::size_t n = 0;
    for (int a = first; a < last; ++a)
      n += near_[m * nlocal + static_cast<std::size_t>(a)].empty() ? 0 : 1;
    thread_tasks_[static_cast<std::size_t>(thread) * nmesh + m] = n;
  }
}

// The threads' counts become their first task per mesh (the serial order: mesh, then thread),
// and the task list and the candidate store are readied for `threads` writers.
void FixTriWall::begin_listing(int threads) {
  const std::size_t nmesh = meshes_.size();
  std::size_t next = 0;
  for (std::size_t m = 0; m < nmesh; ++m)
    for (std::size_t t = 0; t < static_cast<std::size_t>(threads); ++t) {
      const std::size_t n = thread_tasks_[t * nmesh + m];
      thread_tasks_[t * nmesh + m] = next;
      next += n;
    }
  ntasks_ = next;
  if (tasks_.size() < ntasks_)
    tasks_.resize(ntasks_); // tasks are reused: their triangle lists keep their capacity
  candidates_.begin_step(ntasks_, threads);
}

// Particles [first, last)'s tasks, from the thread's first task per mesh (begin_listing); a
// particle near no triangle of a mesh has its kept state for that mesh cleared.
void FixTriWall::write_tasks(int thread, int first, int last) {
  const std::size_t nmesh = meshes_.size();
  const std::size_t nlocal = static_cast<std::size_t>(atom->nlocal);
  for (std::size_t m = 0; m < nmesh; ++m) {
    std::size_t k = thread_tasks_[static_cast<std::size_t>(thread) * nmesh + m];
    for (int a = first; a < last; ++a) {
      std::vector<std::pair<int, int>> &near = near_[m * nlocal + static_cast<std::size_t>(a)];
      if (near.empty()) {
        clear_wall_state(a, static_cast<int>(m));
        continue;
      }
      // Ordered by global triangle id, so the result does not depend on how the mesh is
      // split between ranks.
      std::sort(near.begin(), near.end());
      Task &task = tasks_[k];
      task.atom = a;
      task.mesh = static_cast<int>(m);
      task.triangles.clear();
      task.ids.clear();
      for (const auto &p : near) {
        task.ids.push_back(p.first);
        task.triangles.push_back(p.second);
      }
      near.clear();
      task.candidates =
          settings_.interaction.coherence > 0.0
              ? candidates_.entry(
                    k, tri_liggghts::CandidateStore::wall_key(atom->tag[a], static_cast<int>(m)),
                    thread)
              : nullptr;
      ++k;
    }
  }
}

// Particle a is near no triangle of mesh m: its contact with it, if any, has ended.
void FixTriWall::clear_wall_state(int a, int m) {
  double *h = history_[a] + m * tri::kHistoryDoubles;
  // The history is written compactly (contact_history.h): an empty first slot means an empty
  // history, so most particles far from the walls cost a read, not a fill.
  if (tri::slot_occupied(h, 0))
    std::fill(h, h + tri::kHistoryDoubles, 0.0);
  std::fill(axis(a, m), axis(a, m) + 3, 0.0);
  double *k = kept(a, m);
  if (k && tri::kept_state(k))
    tri::clear_kept_contacts(k);
}

void FixTriWall::build_wall(int k, std::vector<Eigen::Vector3d> &nodes,
                            std::vector<Eigen::Vector3d> &node_velocities) {
  Task &task = tasks_[k];
  TriMesh *mesh = meshes_[task.mesh]->triMesh();
  tri::TriangleSoA &patch = patches_[k];
  const int n = static_cast<int>(task.triangles.size());
  patch.resize(n);
  // Node velocities exist once a fix move/mesh moves the mesh; a static mesh has none.
  auto *vnodes = mesh->prop().getElementProperty<MultiVectorContainer<double, 3, 3>>("v");
  nodes.resize(3 * n);
  node_velocities.assign(3 * n, Eigen::Vector3d::Zero());
  for (int t = 0; t < n; ++t)
    for (int c = 0; c < 3; ++c) {
      double p[3];
      mesh->node(task.triangles[t], c, p);
      nodes[3 * t + c] = Eigen::Vector3d(p[0], p[1], p[2]);
      patch.set_vertex(t, c, nodes[3 * t + c]);
      if (vnodes) {
        const double *v = vnodes->begin()[task.triangles[t]][c];
        node_velocities[3 * t + c] = Eigen::Vector3d(v[0], v[1], v[2]);
      }
    }
  const tri::RigidMotion motion = tri::fit_rigid_motion(nodes.data(), node_velocities.data(), 3 * n);
  tri::Body &wall = task.wall;
  wall = tri::Body{};
  wall.triangles = &patch;
  wall.epsilon = layer_;
  wall.longest_edge = std::numeric_limits<double>::infinity();
  wall.min_edge = particles_->body(task.atom).min_edge;
  wall.state.x = motion.centre;
  wall.state.v = motion.velocity;
  wall.state.omega = motion.omega;
  wall.state.mass = 0.0;
  // A static mesh's patch keeps its contact points against the world frame (its pose the
  // world's: Body's default); a moving one is measured every step.
  task.kept = vnodes ? nullptr : kept(task.atom, task.mesh);
  wall.triangle_ids = task.kept ? task.ids.data() : nullptr;
}

void FixTriWall::prepare(int k, bool update_history, NodeScratch &scratch) {
  build_wall(k, scratch.nodes, scratch.velocities);
  Task &task = tasks_[k];
  task.body = nullptr;
  particles_->ensure_body_of(task.atom);
  task.apart = tri::proven_apart(particles_->body(task.atom), task.wall, settings_.interaction,
                                 separation_cache(task, update_history));
}

template <class Step> auto FixTriWall::in_kernel_view(int k, bool update_history, Step &&step) {
  const Task &task = tasks_[k];
  const int a = task.atom;
  const tri::InteractionSettings &s =
      materials_.settings(atom->type[a], meshes_[task.mesh]->atomTypeWall());
  // (without a history model the values stay zero: the same zero result)
  double *stored = s.coefficients.tangential == tri::TangentialModel::no_history
                       ? nullptr
                       : history_[a] + task.mesh * tri::kHistoryDoubles;
  tri::HistoryView history(stored, false, update_history);
  return step(task.body ? *task.body : particles_->body(a), task.wall, s, history.data());
}

tri::PairPlan FixTriWall::EngineHost::plan(std::size_t k, int thread,
                                           tri::InteractionScratch &scratch,
                                           tri::ContactStats &stats) {
  fix.prepare(static_cast<int>(k), update_history, fix.node_scratch_[thread]);
  if (k + kPrefetchAhead < fix.ntasks_)
    fix.prefetch(fix.tasks_[k + kPrefetchAhead]);
  const Task &task = fix.tasks_[k];
  if (task.apart &&
      tri::apart_needs_nothing(fix.history_[task.atom] + task.mesh * tri::kHistoryDoubles) &&
      !tri::kept_state(task.kept))
    return tri::apart_result(stats);
  // The particle's world-frame triangles, unless apart or carried (both read its pose alone).
  const bool carried = !task.apart && fix.carries_kept_contacts(task);
  if (!task.apart && !carried)
    fix.tasks_[k].body = &fix.particles_->task_body(task.atom, thread, fix.pins_.of(k));
  return fix.in_kernel_view(
      static_cast<int>(k), update_history,
      [&](const tri::Body &particle, const tri::Body &wall, const tri::InteractionSettings &s,
          double *history) -> tri::PairPlan {
        const tri::SeparationCache cache = fix.separation_cache(task, update_history);
        if (carried)
          return tri::carried_contacts_result(particle, wall, s, dt, history, scratch, stats,
                                              cache);
        if (task.apart) {
          if (update_history && tri::kept_state(task.kept))
            tri::clear_kept_contacts(task.kept);
          return tri::apart_result(particle, wall, s, dt, history, scratch, stats);
        }
        return tri::plan_body_pair(particle, wall, s, dt, history, scratch, stats, cache);
      });
}

bool FixTriWall::carries_kept_contacts(const Task &task) {
  if (!tri::contacts_kept(task.kept))
    return false;
  const tri::InteractionSettings &s =
      materials_.settings(atom->type[task.atom], meshes_[task.mesh]->atomTypeWall());
  return tri::kept_contacts_hold(particles_->body(task.atom), task.wall, s,
                                 separation_cache(task, false));
}

tri::PairForceResult FixTriWall::EngineHost::finish(std::size_t k,
                                                    const tri::KernelRequest &request,
                                                    const tri::TrianglePairDistance *results,
                                                    tri::InteractionScratch &scratch,
                                                    tri::ContactStats &stats) {
  const Task &task = fix.tasks_[k];
  return fix.in_kernel_view(
      static_cast<int>(k), update_history,
      [&](const tri::Body &particle, const tri::Body &wall, const tri::InteractionSettings &s,
          double *history) {
        return tri::finish_body_pair(particle, wall, s, dt, history, scratch, stats,
                                     fix.separation_cache(task, update_history), request,
                                     results);
      });
}

void FixTriWall::prefetch(const Task &t) {
  if (t.candidates)
    t.candidates->prefetch();
  const char *h = reinterpret_cast<const char *>(history_[t.atom] + t.mesh * tri::kHistoryDoubles);
  for (std::size_t offset = 0; offset < tri::kHistoryDoubles * sizeof(double); offset += 64)
    __builtin_prefetch(h + offset);
  __builtin_prefetch(axis(t.atom, t.mesh));
}

void FixTriWall::compute(bool update_history, int vflag) {
  const double start = MPI_Wtime();
  if (vflag && virial_flag)
    v_setup(vflag); // zeroes virial and vatom where asked
  else
    evflag = 0;
  collect_tasks();
  if (patches_.size() < ntasks_)
    patches_.resize(ntasks_);
  const int nthreads = tri_liggghts::pair_loop_threads(settings_.loop, ntasks_);
  if (static_cast<int>(node_scratch_.size()) < nthreads)
    node_scratch_.resize(nthreads);
  particles_->prepare_task_bodies(nthreads);
  pins_ = particles_->reserve_pins(ntasks_, nthreads);
  const double dt = update->dt;
  tri_liggghts::ContactBoard &board = particles_->board();
  const bool loads = update_history && std::find(loaded_.begin(), loaded_.end(), 1) != loaded_.end();
  engine_.record_contacts(evflag || board.contacts_wanted() || loads);
  EngineHost host{*this, dt, update_history};
  engine_.run(ntasks_, nthreads, host);
  if (engine_.failed()) {
    const Task &t = tasks_[engine_.failed_task()];
    const std::string msg = std::string(kStyle) + ": the contact kernel failed on particle " +
                            std::to_string(atom->tag[t.atom]) + " and mesh '" +
                            mesh_ids_[t.mesh] + "': " + engine_.failure();
    error->one(FLERR, msg.c_str()); // every rank that failed stops
  }
  tri_liggghts::IntersectingPair first;
  tri_liggghts::DeepestContact deepest;
  for (std::size_t k = 0; k < ntasks_; ++k) {
    const tri::PairForceResult &r = engine_.result(k);
    const int a = tasks_[k].atom;
    if (r.intersecting && !first.found())
      first = {atom->tag[a], 0};
    deepest.consider(r, atom->tag[a], 0, mesh_ids_[tasks_[k].mesh]);
    engine_.set_recipients(k, a, tasks_[k].mesh, -1, 0);
  }
  engine_.apply(atom->f, atom->torque);
  if (evflag) // the particles' terms only: the wall is not an atom
    engine_.add_virial(vflag_global ? virial : nullptr, vflag_atom ? vatom : nullptr);
  publish_contacts();
  if (loads)
    add_wall_loads();
  particles_->board().publish(board_slot_, engine_.tally(), first);
  particles_->board().publish_deepest(board_slot_, deepest);
  seconds_ += MPI_Wtime() - start;
}

void FixTriWall::publish_contacts() {
  tri_liggghts::ContactBoard &board = particles_->board();
  if (!board.contacts_wanted())
    return;
  contact_rows_.clear();
  for (std::size_t k = 0; k < ntasks_; ++k) {
    const Task &task = tasks_[k];
    TriMesh *mesh = meshes_[task.mesh]->triMesh();
    bool first = true;
    for (const tri::ContactRecord &rec : engine_.records(k)) {
      const long triangle = rec.tri_b >= 0 && rec.tri_b < static_cast<int>(task.triangles.size())
                                ? static_cast<long>(mesh->id(task.triangles[rec.tri_b]))
                                : -1L;
      contact_rows_.push_back({task.atom, -1, task.mesh, triangle, k, first, rec});
      first = false;
    }
  }
  board.publish_contacts(board_slot_, contact_rows_);
}

void FixTriWall::add_wall_loads() {
  for (std::size_t k = 0; k < ntasks_; ++k) {
    const Task &task = tasks_[k];
    if (!loaded_[task.mesh])
      continue;
    const double *x = atom->x[task.atom];
    for (const tri::ContactRecord &rec : engine_.records(k)) {
      if (rec.tri_b < 0 || rec.tri_b >= static_cast<int>(task.triangles.size()))
        continue;
      // LIGGGHTS takes the force on the particle and turns it round in place: a copy each time.
      const Eigen::Vector3d on_particle = -rec.force_on_b();
      double force[3] = {on_particle.x(), on_particle.y(), on_particle.z()};
      double delta[3] = {rec.point.x() - x[0], rec.point.y() - x[1], rec.point.z() - x[2]};
      double v_wall[3] = {rec.velocity_b.x(), rec.velocity_b.y(), rec.velocity_b.z()};
      meshes_[task.mesh]->add_particle_contribution(task.atom, force, delta,
                                                    task.triangles[rec.tri_b], v_wall);
    }
  }
}

/* ---------------- per-atom wall history ---------------- */

void FixTriWall::grow_arrays(int nmax) {
  memory->grow(history_, nmax, std::max(values_per_atom_, 1), "tri/wall:history");
}

void FixTriWall::copy_arrays(int i, int j, int) {
  std::memcpy(history_[j], history_[i], values_per_atom_ * sizeof(double));
}

int FixTriWall::pack_exchange(int i, double *buf) {
  std::memcpy(buf, history_[i], values_per_atom_ * sizeof(double));
  return values_per_atom_;
}

int FixTriWall::unpack_exchange(int nlocal, double *buf) {
  std::memcpy(history_[nlocal], buf, values_per_atom_ * sizeof(double));
  return values_per_atom_;
}

int FixTriWall::pack_restart(int i, double *buf) {
  buf[0] = values_per_atom_ + 1;
  std::memcpy(buf + 1, history_[i], values_per_atom_ * sizeof(double));
  return values_per_atom_ + 1;
}

void FixTriWall::unpack_restart(int nlocal, int nth) {
  const double *record = tri_liggghts::restart_record(atom->extra, nlocal, nth);
  const int stored = static_cast<int>(record[-1]) - 1; // the record's length prefix
  // Without kept contact points (written with keep_contacts no, or before they existed), with
  // them where this run keeps none, or with points of the layout that held no patch (11 values
  // a point, 31 a record): the history and axes are read, kept points start empty.
  const int meshes = static_cast<int>(meshes_.size());
  const int with_kept = values_without_kept_ + meshes * tri::kKeptContactDoubles;
  const int with_point_only_kept = values_without_kept_ + meshes * 31;
  if (stored != values_without_kept_ && stored != with_kept && stored != with_point_only_kept) {
    const std::string msg =
        std::string(kStyle) + ": the restart file holds " + std::to_string(stored) +
        " wall history values per particle, this build keeps " +
        std::to_string(values_per_atom_) + " (" + std::to_string(tri::kHistoryDoubles) +
        " per mesh): it was written by another version or with other meshes";
    error->one(FLERR, msg.c_str());
  }
  const int read = stored == with_kept ? std::min(stored, values_per_atom_) : values_without_kept_;
  std::fill(history_[nlocal], history_[nlocal] + values_per_atom_, 0.0);
  std::memcpy(history_[nlocal], record, read * sizeof(double));
}

int FixTriWall::size_restart(int) { return values_per_atom_ + 1; }
int FixTriWall::maxsize_restart() { return values_per_atom_ + 1; }

double FixTriWall::memory_usage() {
  double bytes = static_cast<double>(atom->nmax) * values_per_atom_ * sizeof(double);
  for (const tri::TriangleSoA &patch : patches_)
    bytes += 3.0 * patch.x.capacity() * sizeof(double);
  for (const Task &task : tasks_)
    bytes += (task.triangles.capacity() + task.ids.capacity()) * sizeof(int);
  for (const std::vector<std::pair<int, int>> &near : near_)
    bytes += sizeof(near) + near.capacity() * sizeof(std::pair<int, int>);
  for (const NodeScratch &s : node_scratch_)
    bytes += (s.nodes.capacity() + s.velocities.capacity()) * sizeof(Eigen::Vector3d);
  return bytes + static_cast<double>(engine_.bytes()) + static_cast<double>(candidates_.bytes());
}
