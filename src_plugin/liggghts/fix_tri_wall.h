// fix tri/wall: contacts between triangulated particles and the triangles of one or more
// LIGGGHTS `fix mesh/surface` meshes (static, or moved by `fix move/mesh`). Wall triangles
// near a particle come from LIGGGHTS's own mesh neighbour list (`neighlist/mesh`, the one
// `fix wall/gran` uses), so the cost grows with the particles near each wall triangle. The
// particle's triangles and those wall triangles meet in the kernel (body_interaction.h): the
// same search, reduction and force law as pair tri/gran; the wall material is the mesh's type.
//
//   fix ID group tri/wall mesh MESH_ID [MESH_ID ...] [epsilon E] [virial yes|no]
//                         [model hooke/stiffness|hooke|hertz]
//                         [contact keywords]
//
// A wall patch is a body of infinite mass moving as the mesh moves: its rigid velocity field is
// fitted to the node velocities of the patch (tri/rigid_motion.h), exact for move/mesh's rigid
// motions, so a particle on a rotating drum is carried at the drum's surface velocity. The
// loop, scratch, errors and ordered sums are tri::InteractionEngine's, as for pair tri/gran;
// the tallies go to the contact board of fix tri/particles.
//
// virial yes|no (default yes): the wall's forces on the particles count in compute pressure and
// stress/atom, each particle's (x - p) (x) F per contact (contact_force.h Virial), where
// LIGGGHTS asks for the virial.
// epsilon: the wall's soft layer (m), default the particles' epsilon. Contact keywords as
// pair tri/gran (contact_settings.h). Wall loads: a mesh/surface with `stress on` (LIGGGHTS's
// stress module) gets each contact point's force on the wall, on the wall triangle of its
// deepest member, as fix wall/gran gives it (f_MESH[1..3] the total force, [4..6] the torque
// about its reference point; the per-triangle forces for dump mesh/vtk). f_ID (a global scalar) is the wall-clock time spent in
// this fix, for a run's time breakdown. The tangential history of each (particle, mesh) pair,
// its last proven separating axis (a particle that touches no wall triangle near it costs
// O(vertices)) and, on a static mesh, its kept contact points (keep_contacts:
// interaction/kept_contacts.h) are a per-atom array of this fix: migrated with the atom and
// written to restarts.
#pragma once

#include "fix.h"

#include "candidate_store.h"
#include "contact_board.h"
#include "contact_settings.h"
#include "interaction/interaction_engine.h"
#include "material_table.h"
#include "world_cache.h"

#include <vector>

namespace LAMMPS_NS {

class FixTriWall : public Fix {
public:
  FixTriWall(class LAMMPS *, int, char **);
  ~FixTriWall() override;
  int setmask() override;
  void post_create() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

  // Wall-clock seconds this fix has spent computing forces since the fix was created (for the
  // time breakdown of a run: LIGGGHTS counts it under "Other"). f_ID in thermo.
  double compute_scalar() override { return seconds_; }

private:
  struct Task {
    int atom, mesh;
    std::vector<int> triangles; // mesh-local indices, ordered by global triangle id
    std::vector<int> ids;       // their global ids (the kept contact points name them)
    tri::CandidateCache *candidates = nullptr; // kept candidates of (atom, mesh), or null
    double *kept = nullptr; // the kept contact points of (atom, mesh), a static mesh's; or null
    tri::Body wall;     // the patch (patches_[k]) as the kernel sees it (prepare)
    bool apart = false; // proven apart by its kept gap or axis (prepare)
    // Not apart: the particle with its world-frame triangles (FixTriParticles::task_body).
    const tri::Body *body = nullptr;
  };
  tri_liggghts::TaskPins pins_; // this step's (task_body)
  std::vector<class FixMeshSurface *> meshes_;
  std::vector<std::string> mesh_ids_;
  std::vector<char> loaded_; // per mesh: tracks its stress (wall loads wanted); from init
  class FixTriParticles *particles_ = nullptr;
  tri_liggghts::ContactSettings settings_;
  tri_liggghts::MaterialTable materials_;
  double epsilon_ = -1.0; // `epsilon E`; < 0: none given
  // The wall's soft layer, m: E, or the particles' default for walls (none with the layer
  // inside the particles: the wall's mesh is its contact surface).
  double layer_ = 0.0;
  // per atom: meshes_.size() * (kHistoryDoubles + 3), then with keep_contacts
  // meshes_.size() * kKeptContactDoubles (kept contact points, interaction/kept_contacts.h)
  double **history_ = nullptr;
  int values_per_atom_ = 0;
  int values_without_kept_ = 0; // what a restart file written before kept points holds
  // The kept contact points of (atom a, mesh m); null without keep_contacts.
  double *kept(int a, int m) {
    if (values_per_atom_ == values_without_kept_)
      return nullptr;
    return history_[a] + values_without_kept_ + tri::kKeptContactDoubles * static_cast<std::size_t>(m);
  }
  // The separating axis of (atom a, mesh m), particle towards wall (body_interaction.h).
  double *axis(int a, int m) {
    return history_[a] + meshes_.size() * tri::kHistoryDoubles + 3 * static_cast<std::size_t>(m);
  }
  std::vector<Task> tasks_; // the first ntasks_ are this step's
  std::size_t ntasks_ = 0;
  // per mesh and particle, its triangles near the particle (list_near_triangles)
  std::vector<std::vector<std::pair<int, int>>> near_;
  std::vector<std::size_t> thread_tasks_; // per thread and mesh: its tasks, then its first
  std::vector<tri::TriangleSoA> patches_;
  struct NodeScratch { // build_wall's, one per thread
    std::vector<Eigen::Vector3d> nodes, velocities;
  };
  std::vector<NodeScratch> node_scratch_;
  tri::InteractionEngine engine_;
  tri_liggghts::CandidateStore candidates_;
  int board_slot_ = -1;
  double seconds_ = 0.0;

  std::vector<tri_liggghts::PublishedContact> contact_rows_; // refilled when published
  // One force evaluation; vflag as LIGGGHTS passes it (the virial where it asks).
  void compute(bool update_history, int vflag);
  // The step's contact records on the board, where a contact output wants them.
  void publish_contacts();
  void add_wall_loads();
  void collect_tasks();
  void list_near_triangles(int m);
  void count_tasks(int thread, int first, int last);
  void begin_listing(int threads);
  void write_tasks(int thread, int first, int last);
  void clear_wall_state(int a, int m);
  // A task's kept state (candidates, the atom's history and axis for this mesh) lies wherever
  // its entry and atom are: asked for kPrefetchAhead tasks ahead, as pair tri/gran does, it
  // arrives while the tasks before it run.
  static constexpr std::size_t kPrefetchAhead = 2;
  void prefetch(const Task &t);
  // A task's first work, on the engine's thread that evaluates it: its wall patch and Body, its
  // particle's Body record; then whether its kept gap or axis proves it apart from the
  // particle's pose (tri::proven_apart: no world-frame particle triangles needed; the other
  // tasks ask for them as they go on, FixTriParticles::ensure_world_triangles_of).
  void prepare(int k, bool update_history, NodeScratch &scratch);
  // Whether task k's kept contact points hold this step (tri::kept_contacts_hold, from the
  // particle's pose): then its world-frame triangles are not needed.
  bool carries_kept_contacts(const Task &task);
  void build_wall(int k, std::vector<Eigen::Vector3d> &nodes,
                  std::vector<Eigen::Vector3d> &node_velocities);
  // Runs step(particle, wall, settings, history) on task k, its history viewed as the kernel
  // sees it and written back after the step.
  template <class Step> auto in_kernel_view(int k, bool update_history, Step &&step);
  tri::SeparationCache separation_cache(const Task &task, bool update_history) {
    return {settings_.separation ? axis(task.atom, task.mesh) : nullptr, update_history,
            task.candidates, {}, task.kept};
  }
  // What the engine asks of this fix for task k (interaction_engine.h: the host).
  struct EngineHost {
    FixTriWall &fix;
    double dt;
    bool update_history;
    tri::PairPlan plan(std::size_t k, int thread, tri::InteractionScratch &scratch,
                       tri::ContactStats &stats);
    tri::PairForceResult finish(std::size_t k, const tri::KernelRequest &request,
                                const tri::TrianglePairDistance *results,
                                tri::InteractionScratch &scratch, tri::ContactStats &stats);
    void complete(std::size_t, tri::PairForceResult &) {} // all after the loop
  };
};

} // namespace LAMMPS_NS
