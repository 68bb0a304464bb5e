// pair_style tri/gran: contact forces between triangulated particles (fix tri/particles).
// LIGGGHTS's granular neighbour list (radius = the contact reach) gives candidate
// pairs; for each pair whose bounding spheres overlap, the kernel (body_interaction.h) finds
// the triangle pairs within the soft layers, reduces them to contact points and applies the
// hooke/stiffness force law with friction; forces and torques go to both particles.
//
//   pair_style tri/gran [model hooke/stiffness|hooke|hertz] [contact keywords, see
//                       contact_settings.h]
//   pair_coeff * *
//
// The material (material_table.h) is read in init_style, before LIGGGHTS sizes the neighbour
// cutoffs from the particles' radii, and published on the contact board, so that fix
// tri/particles can resolve `epsilon auto` from it first (material_scales.h).
//
// Built on LIGGGHTS's PairGran, so the tangential history lives in LIGGGHTS's own contact
// history (fix contacthistory): it survives neighbour-list rebuilds, migration between ranks
// and restarts. Requires newton_pair off, as every granular history pair style. The same
// storage keeps each pair's last proven separating axis (body_interaction.h, three values
// after the tangential ones), so a pair within reach that touches nothing costs O(vertices)
// per step; the forces do not depend on it. Pairs within reach keep their triangle-pair
// candidates between steps (candidate_store.h, keyword `coherence`); nor do the forces depend
// on those. Pairs in contact keep their contact points (keep_contacts, default 1e-4 of the
// layer: interaction/kept_contacts.h), carried with the bodies while their relative motion
// stays within that tolerance, and measured again beyond it; the points live in fix
// tri/kept_contacts (kept_contact_store.h), which this style creates and which moves them with
// the atoms between ranks and into restart files.
//
// The loop, scratch, error capture and ordered sums are tri::InteractionEngine's (shared with
// fix tri/wall); this style lists the pairs and says what its two bodies are (EngineHost). It
// publishes its tallies and its neighbour list on the contact board of fix tri/particles.
//
// Determinism: the per-pair work (OpenMP over particle pairs, or inside one pair) writes
// results into a per-pair slot, and one thread sums them afterwards, so the result does not
// depend on the thread count. It does not depend on the number of MPI ranks either: every
// pair is evaluated as (lower atom tag, higher atom tag), whichever atom the rank owns and
// whichever order the neighbour list has them in (the kernel's force for (b, a) equals minus
// that for (a, b) only to rounding), and the contributions to an atom are summed in
// the order of the partners' tags, not the neighbour list's, which follows the decomposition.
// So a pair's force is bitwise the same on every rank that evaluates it, and so is each
// atom's total.
//
// Virial (compute pressure, stress/atom), where LIGGGHTS asks for it: per contact point, each
// particle's (x - p) (x) F over the forces F on it and the points p where they act (contact_force.h
// Virial; for spheres the sum over both is LIGGGHTS's pair virial), tallied for the atoms this
// rank owns (with newton off a pair across ranks counts each atom's term on its own rank: the
// pair once over all ranks), summed in the engine's order: independent of the thread count.
#pragma once

#include "pair_gran.h"

#include "approach_speed.h"
#include "candidate_store.h"
#include "contact_board.h"
#include "contact_settings.h"
#include "kept_contact_store.h"
#include "interaction/interaction_engine.h"
#include "material_table.h"
#include "particle_travel.h"
#include "world_cache.h"

#include <cstdint>
#include <vector>

namespace LAMMPS_NS {

class PairTriGran : public PairGran {
public:
  explicit PairTriGran(class LAMMPS *);
  void settings(int, char **) override;
  void init_style() override;
  bool contact_match(const std::string, const std::string) override { return false; }
  int64_t hashcode() override { return 0x7472692f6772616eLL; } // "tri/gran"
  double stressStrainExponent() override { return 1.0; }

protected:
  void compute_force(int eflag, int vflag, int addflag) override;

private:
  struct Task {
    int i, j;
    bool swapped;    // evaluated as (j, i): tag[j] < tag[i]
    double *history; // kHistoryDoubles values in LIGGGHTS's contact history, or null
    double *axis;    // the pair's separating axis (3 values, as seen from (i, j)), or null
    double *touching_values; // all of this pair style's history values, or null
    int *touching;   // LIGGGHTS keeps (migrates, restarts) the history only where this is set
    tri::CandidateCache *candidates; // the pair's kept candidates, or null
    double *kept; // the pair's kept contact points (kept_contact_store.h), or null
    bool apart = false; // proven apart by its kept gap or axis, from the poses (prepare)
    // Not apart: its atoms with their world-frame triangles (FixTriParticles::task_body).
    const tri::Body *body_i = nullptr, *body_j = nullptr;
  };
  static constexpr std::size_t kPrefetchAhead = 2;
  void prefetch(const Task &t);
  // A task as the kernel sees it: (a, b) in tag order, its axis copied with the sign of (a, b).
  struct TaskView {
    int a, b;
    double sign;
    double axis[3];
  };
  static TaskView view(const Task &task);
  // Runs step(a, b, settings, history, cache) on a task as the kernel sees it: its bodies in
  // tag order, its history and axis viewed from (a, b) and written back after the step.
  template <class Step> auto in_kernel_view(const Task &task, bool update_history, Step &&step);
  // A task's first work, on the engine's thread that runs it: its atoms' Body records,
  // and `apart` (tri::proven_apart, from those records without their triangles): only the
  // other tasks' atoms need world-frame triangles this step.
  void prepare(Task &task, bool update_history);
  // Whether the task's kept contact points hold this step (tri::kept_contacts_hold, from the
  // poses): then its atoms' world-frame triangles are not needed.
  bool carries_kept_contacts(const Task &task);
  void find_kept_contacts();
  std::uint64_t kept_key(int i, int j) const;
  // What the engine asks of this style for task k (interaction_engine.h: the host).
  struct EngineHost {
    PairTriGran &style;
    double dt;
    bool update_history, newton;
    int nlocal;
    tri::PairPlan plan(std::size_t k, int thread, tri::InteractionScratch &scratch,
                       tri::ContactStats &stats);
    tri::PairForceResult finish(std::size_t k, const tri::KernelRequest &request,
                                const tri::TrianglePairDistance *results,
                                tri::InteractionScratch &scratch, tri::ContactStats &stats);
    // The task's own bookkeeping (its energy's share, LIGGGHTS's touch flag, its recipients,
    // the run-safety geometry), on the threads rather than after the loop.
    void complete(std::size_t k, tri::PairForceResult &r);
  };
  class FixTriParticles *particles_ = nullptr;
  int board_slot_ = -1;
  tri_liggghts::ContactSettings settings_;
  tri_liggghts::MaterialTable materials_;
  std::vector<Task> tasks_;
  tri_liggghts::TaskPins pins_; // this step's (task_body)
  std::vector<tri_liggghts::PairGeometry> task_geometry_; // per task, for the run-safety check
  tri::InteractionEngine engine_;
  tri_liggghts::CandidateStore candidates_;
  int axis_offset_ = -1; // where the separating axis starts in a pair's history values
  tri_liggghts::KeptContactStore *kept_ = nullptr; // fix tri/kept_contacts's; null: none kept
  // Pairs within reach that the travel proof passed over while listing (no task): as tasks they
  // would be proven apart and change nothing (their history is clear: the evaluation that kept
  // their gap cleared it). `before`: the number of tasks listed before it, so that the fastest
  // pair is looked for in the order of the neighbour list, as among tasks.
  struct PassedPair {
    std::size_t before;
    tri_liggghts::PairGeometry geometry;
    tagint tag_i, tag_j;
  };
  std::vector<PassedPair> passed_;
  tri_liggghts::ParticleTravel travel_;
  // The listing on several threads (collect_tasks): a run of neighbour rows, and what one
  // thread lists from its run before the runs' lists are joined.
  struct RowRange {
    int first = 0, last = 0; // rows [first, last) of the neighbour list
    std::size_t slot = 0;    // the stores' slot of the run's first neighbour pair
  };
  struct RowList {
    std::vector<Task> tasks;
    std::vector<PassedPair> passed;
  };
  std::vector<RowList> row_lists_; // one per thread
  std::vector<RowRange> split_rows(std::size_t neighbour_pairs, int threads) const;
  void collect_rows(RowRange rows, int lane, std::vector<Task> &tasks,
                    std::vector<PassedPair> &passed);

  // What the run-safety check reads of a step (summarize): over a run of tasks, or the step.
  struct StepSummary {
    tri_liggghts::IntersectingPair first;
    tri_liggghts::DeepestContact deepest;
    tri_liggghts::FastestPair fastest;
    void merge(const StepSummary &later);
  };
  static constexpr std::size_t kSummaryTasks = 256;
  std::vector<StepSummary> summaries_; // per block of kSummaryTasks tasks
  StepSummary summarize_tasks(std::size_t first_task, std::size_t last_task, bool trailing) const;
  StepSummary summarize(int threads);

  std::vector<tri_liggghts::PublishedContact> contact_rows_; // refilled when published
  void collect_tasks();
  // The step's contact records on the board, where a contact output wants them.
  void publish_contacts();
  void report_failure();
  double memory_usage() override;
};

} // namespace LAMMPS_NS
