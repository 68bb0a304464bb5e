// fix tri/particles: makes every atom of an `atom_style sphere` system a rigid triangulated
// particle. It owns the shape templates and, per atom, the shape index, the orientation
// quaternion and the angular momentum, as one LIGGGHTS per-atom array that is grown, copied,
// migrated, sent to ghosts and written to restarts like any LIGGGHTS property. It sets
// radius := the shape's contact reach (tri::contact_reach: the given mesh's bounding radius,
// with `layer outside` plus epsilon; so LIGGGHTS's neighbour lists find every pair that can
// touch) and rmass := density * volume. The contact kernel measures each shape's surface offset
// inward by epsilon (`layer inside`, the default: kernel/body/inner_surface.h), so the given mesh
// is the contact surface. World-frame triangles are built on
// demand, once per force evaluation, for the atoms the contact styles and the output ask for.
//
// Shapes are built by shape_builder.h. It owns the contact board (contact_board.h) on which
// the contact styles publish their tallies, and the run-safety checks (run_safety_monitor.h:
// intersections at the start, steps too long for the soft layer) that read it in post_force
// and end_of_step.
//
// The per-atom array is visible to dumps as f_ID[1..8]: shape index, quaternion w x y z
// (body principal frame -> space), angular momentum Lx Ly Lz (space frame, kg m^2/s).
//
// Particles that fix insert/* inserts from particletemplate/sphere get their shape from the
// template (particle_insertion.h, fix_tri_template_sphere.h) and arrive during a run without
// a tag; pre_force initialises them (orientation, mass, radius) once they have one.
#pragma once

#include "atom.h"
#include "fix.h"

#include "body/shape.h"
#include "contact_board.h"
#include "geometry/triangle_soa.h"
#include "interaction/body_interaction.h"
#include "material_scales.h"
#include "run_safety_monitor.h"
#include "world_cache.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class FixTriParticles : public Fix {
public:
  static constexpr int kValues = 8; // shape, q(4), L(3): what dumps see as f_ID[1..8]
  // A second per-atom array: the force and torque of the step a restart file was written at,
  // and a flag that they are pending (see take_restored_force_and_torque). Kept apart from the
  // first, whose row length LIGGGHTS's variables and dumps assume to be kValues.
  static constexpr int kPending = 7;
  static constexpr int kQuatColumn = 1, kAngmomColumn = 5; // of the first array

  FixTriParticles(class LAMMPS *, int, char **);
  ~FixTriParticles() override;
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void pre_force(int) override;
  void post_force(int) override;
  void end_of_step() override;
  void post_run() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_border(int, int *, double *) override;
  int unpack_border(int, int, double *) override;
  int pack_comm(int, int *, double *, int, int *) override;
  void unpack_comm(int, int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  double max_rad(int type) override;
  double memory_usage() override;

  // For the other tri/ styles.
  int num_shapes() const { return static_cast<int>(shapes_.size()); }
  const tri::Shape &shape(int s) const { return shapes_[s]; }
  int shape_index(int i) const { return static_cast<int>(state_[i][0]); }
  // Inline: fix tri/nve calls these for every particle twice a step.
  Eigen::Quaterniond orientation(int i) const {
    const double *q = state_[i] + kQuatColumn;
    return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  }
  void set_orientation(int i, const Eigen::Quaterniond &q) {
    double *d = state_[i] + kQuatColumn;
    d[0] = q.w();
    d[1] = q.x();
    d[2] = q.y();
    d[3] = q.z();
  }
  Eigen::Vector3d angular_momentum(int i) const {
    const double *L = state_[i] + kAngmomColumn;
    return {L[0], L[1], L[2]};
  }
  void set_angular_momentum(int i, const Eigen::Vector3d &L) {
    double *d = state_[i] + kAngmomColumn;
    d[0] = L.x();
    d[1] = L.y();
    d[2] = L.z();
  }
  // The same in place, (w, x, y, z) and (Lx, Ly, Lz): fix tri/nve's per-step loops.
  double *orientation_data(int i) { return state_[i] + kQuatColumn; }
  double *angular_momentum_data(int i) { return state_[i] + kAngmomColumn; }
  // A continuous run starts step N+1 with the forces of step N, which depend on the half-step
  // velocity v(N - 1/2); a run continued from a restart file can only recompute them from
  // v(N). So the restart file carries the step-N force and torque of each particle, and the
  // first time integration after read_restart takes them from here (once; true if it did),
  // which makes "N steps + restart + N steps" bitwise equal to "2N steps".
  bool take_restored_force_and_torque(int i, double *f, double *torque);
  // The same for every atom of the group (fix tri/nve, each step): a test of one flag unless
  // a restart file (or an atom migrating with its record) left something pending on this rank.
  void take_restored_forces_and_torques(int groupbit);
  // Principal moments of atom i, kg m^2, scaled with its rmass (so `set mass` stays consistent).
  Eigen::Vector3d principal_inertia(int i) const {
    const tri::Shape &s = shapes_[shape_index(i)];
    return (atom->rmass[i] / s.volume) * s.inertia_per_density;
  }
  double epsilon() const { return epsilon_; }
  // m, the largest lift of the shapes' surfaces (tri::Shape::ball_lift, surface_lift; 0 where
  // all are their facets): a particle pair's triangle search may reach that much further on
  // each side (tri::Body::reach_epsilon, tri::particle_pair_cutoff).
  double largest_lift() const {
    double most = 0.0;
    for (const tri::Shape &s : shapes_)
      most = std::max({most, s.ball_lift, s.surface_lift});
    return most;
  }
  // True with `layer inside` (the default): the soft layer lies inside the given meshes.
  bool layer_inside() const { return layer_inside_; }
  // A wall's soft layer when fix tri/wall gives none (m): none with the layer inside (a wall's
  // mesh is its contact surface), the particles' epsilon with `layer outside`.
  double default_wall_layer() const { return layer_inside_ ? 0.0 : epsilon_; }
  // LIGGGHTS radius of a particle of shape s (tri::contact_reach).
  double reach(int s) const { return tri::contact_reach(shapes_[s], epsilon_); }
  // The given surface of owned atom i in the world frame (output: fix tri/vtk).
  void given_surface(int i, tri::TriangleSoA &out) const;
  // `epsilon auto`: a contact style calls this at its init, after publishing its material on
  // the board, before anything is sized from the radii (material_scales.h). Sets epsilon, the
  // shapes' inner surfaces and the radii; a no-op with an explicit epsilon. Once resolved, a
  // later source before the first run may only widen it, and only with the layer inside.
  void resolve_epsilon();
  // The bodies each atom type can be (its shapes), for the contact styles' materials.
  tri_liggghts::TypeBodies type_bodies() const;
  // Where the contact styles publish, and their readers read (contact_board.h).
  tri_liggghts::ContactBoard &board() { return board_; }
  // The board for a reader (a compute): what the last force evaluation published. A run with
  // `pre no` skips init and setup, so its sources have not joined again when thermo reads its
  // first row: they, and their last tallies, are taken back first.
  const tri_liggghts::ContactBoard &published() {
    rejoin_after_run_pre_no();
    return board_;
  }
  // World-frame triangles of owned and ghost atom i: valid once ensure_world_triangles_of(i) or
  // update_world_triangles has included i in this force evaluation.
  const tri::TriangleSoA &world_triangles(int i) const { return world_[i]; }
  // Atom i (owned or ghost) as the contact kernel sees it: its world-frame triangles, soft
  // layer, edge lengths, and x, v, omega, rmass. Valid like world_triangles(i): built with
  // them, by the thread that transforms the atom, so that a contact style's tasks read one
  // compact record (the same values: nothing changes x, v or omega between pre_force and the
  // contact styles) instead of five per-atom arrays that the integrator wrote on another core.
  // Before that, ensure_body_of builds the record without the triangles (pose, state, frame):
  // enough for the kernel to prove a pair apart by its kept gap or axis (tri::proven_apart).
  const tri::Body &body(int i) const { return bodies_[i]; }
  // Storage for every owned and ghost atom's record and triangles: called by a contact style,
  // outside its parallel loop, before it asks for any (pre_force sizes it too).
  void prepare_bodies();
  // Atom i's Body record (not its world-frame triangles), at most once per force evaluation
  // (pre_force starts a new one). Callable from a contact style's parallel loop, like
  // ensure_world_triangles_of: the first task that needs the record builds it on its thread,
  // so a step has no separate pass over the tasks' atoms.
  void ensure_body_of(int i);
  // World-frame triangles only where needed, each atom's computed from x and
  // its quaternion at most once per force evaluation. For atoms [0, n), outside a parallel
  // loop (output):
  void update_world_triangles(int n);
  // For one atom, from inside a contact style's parallel loop: the first
  // task (on any thread) that needs atom i transforms it and the others wait for it. Builds the
  // Body record too, if no task has yet. The contact styles take task_body instead, and this
  // only where its cache has no room.
  void ensure_world_triangles_of(int i);
  // For a contact style's task on thread `thread`: atom i's Body record with its world-frame
  // triangles, from the thread's WorldCache (world_cache.h), pinned for `pin` (the task's group
  // of tasks: reserve_pins), or the atom's own record and triangles where the cache has no
  // room. Valid while that group's tasks run. The caller sizes the caches first, outside its
  // parallel loop (prepare_task_bodies), and reserves one pin per group. Computed just before
  // they are read, in a table a thread reuses from task to task, the triangles are in that
  // core's cache when the kernel gathers them: computed for every atom first, a pile's 3 MB
  // had left the cache by then; kept per atom, a bed of 8192 rocks' 24 MB left the L3 between
  // one step and the next. Either way the same bits.
  const tri::Body &task_body(int i, int thread, long long pin);
  void prepare_task_bodies(int threads);
  // The pins of an engine run of `tasks` tasks on `threads` threads (world_cache.h).
  tri_liggghts::TaskPins reserve_pins(std::size_t tasks, int threads);
  // Insertion (particle_insertion.h): the rules a template's shape follows, and atom i, just
  // inserted by a template with a shape (no tag yet), is given that shape.
  bool assigns_by_type() const { return assign_by_type_; }
  double density() const { return density_; }
  const std::vector<std::pair<std::string, int>> &template_shapes() const { return templates_; }
  void set_inserted_shape(int i, int shape);

private:
  std::vector<tri::Shape> shapes_;
  std::vector<tri::TriangleSoA> world_;
  std::vector<tri::Body> bodies_;      // per atom, with world_ (body())
  void size_world(std::size_t n);      // world_, bodies_ and stamps for n atoms
  // Per atom: the evaluation its world_ is of; minus it while a thread is transforming it
  // (ensure_world_triangles_of, read and claimed atomically there).
  std::vector<long long> world_stamp_;
  std::vector<long long> body_stamp_;  // per atom: the same for its Body record (ensure_body_of)
  long long evaluation_ = 1;           // force evaluations so far + 1 (pre_force)
  std::vector<tri_liggghts::WorldCache> task_caches_; // one per thread (task_body)
  long long next_pin_ = 0;
  void build_body(int i);              // bodies_[i] without its triangles
  void transform_atom(int i);          // bodies_[i] (if not built yet) and world_[i]
  // Shape s's triangles placed by b's pose into `out`: the one transform of world_ and the
  // task caches, so that both hold the same bits.
  void place_triangles(int s, const tri::Body &b, tri::TriangleSoA &out) const;
  // Runs `work` once this force evaluation for the atom whose stamp is `stamp`, whichever
  // thread comes first; the others wait until it is done.
  template <class Work> void once_this_evaluation(long long *stamp, Work work);
  void rejoin_after_run_pre_no();
  void report_parallelism() const;
  double density_ = 0.0, epsilon_ = 0.0;
  bool epsilon_auto_ = false, epsilon_resolved_ = false;
  bool layer_inside_ = true;
  bool run_started_ = false; // epsilon auto is fixed once the first run has started
  bool initialised_since_run_ = false; // init() since the last run (false: `run N pre no`)
  int check_timestep_every_ = 0; // -1 off, 0 at setup, N: also every N steps
  bool assign_by_type_ = false, orient_random_ = false, orient_file_ = false;
  std::vector<std::pair<std::string, int>> templates_; // `template ID SHAPE`, shape index
  std::uint64_t assign_seed_ = 0, orient_seed_ = 0;
  double **state_ = nullptr;
  double **pending_ = nullptr; // per atom: f(3), torque(3), flag
  // Some atom of this rank may have its flag set (read_restart, or one arrived with it); false
  // once every pending atom was taken, so a step pays no per-atom look.
  bool any_pending_ = false;

  tri_liggghts::ContactBoard board_;
  std::unique_ptr<tri_liggghts::RunSafetyMonitor> monitor_;
  void initialise_atom(int i, int shape = -1); // shape < 0: by the assign rule
  int initialise_unset_atoms();
  void apply_mass_and_radius(int i);
  // Each shape's kernel surface for the current epsilon (tri::with_soft_layer); an ERROR naming
  // the shape when the layer does not fit it.
  void set_soft_layers();
  // epsilon_ := epsilon, resolved: the soft layers, the shapes' check, radii and masses follow;
  // `line` is printed (rank 0) to say where it came from.
  void adopt_epsilon(double epsilon, const char *line);
  void warn_of_changed_radii();
  void bring_contact_history_up_to_date();
};

} // namespace LAMMPS_NS
