// The contact board: where contact-producing styles (pair tri/gran, every fix tri/wall, and
// any later one) publish what others need to know of their force evaluation, and where those
// others (compute tri/stats, fix tri/adapt_dt, the run-safety checks) read it. Readers never
// look a source up by style name or cast to it; a new source joins and publishes, and every
// reader sees it. Owned by fix tri/particles.
//
// Life cycle: a source joins at its init() (idempotent per style ID) and publishes once per
// force evaluation (setup included). At init it also publishes its material hint (the normal
// stiffness of each pair of types it has contacts of), which fix tri/particles reads to size
// `epsilon auto` and to check the time step (material_scales.h); fix tri/adapt_dt publishes
// the range of its time step. Fix tri/particles clears every tally before each force
// evaluation (pre_force) and the membership after each run (post_run), so a style removed
// between runs (unfix, a new pair_style) leaves nothing behind; a run with `pre no` (no init)
// takes the last run's membership back.
// Local to this rank: the cross-rank sums are step_tally.h's.
// LIGGGHTS-free (NeighList is only pointed to), so it is tested alone.
#pragma once

#include "approach_speed.h"
#include "interaction/interaction_tally.h"
#include "model/contact_force.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
class NeighList;
}

namespace tri_liggghts {

enum class SourceKind { particle_pairs, walls };
enum class TallySource { all, pair, wall };

// The first body pair of an evaluation (in its task order) whose real surfaces intersect, by
// atom tags; tag_b is 0 for a wall, both 0 for none.
struct IntersectingPair {
  long tag_a = 0, tag_b = 0;
  bool found() const { return tag_a != 0; }
  void merge(const IntersectingPair &later) { // the first of this one's pairs, then later's
    if (!found())
      *this = later;
  }
};

// The contact of an evaluation that reaches deepest past its soft layers, relative to the depth
// the model resolves (penetration_depth.h), for the run-safety error. depth_of_limit 0: none.
struct DeepestContact {
  double depth_of_limit = 0.0; // (overlap - layer) / limit
  double overlap = 0.0, layer = 0.0, limit = 0.0; // m
  long tag_a = 0, tag_b = 0;   // tag_b 0: a wall
  std::string wall;            // a wall's mesh ID
  // Keeps this interaction if it reaches strictly deeper (ties: the first, in task order).
  void consider(const tri::PairForceResult &r, long tag_a, long tag_b,
                const std::string &wall = std::string());
  // The same over the interactions considered by `later` after this one's.
  void merge(const DeepestContact &later) {
    if (later.depth_of_limit > depth_of_limit)
      *this = later;
  }
};

// What a source's material says about the scales of its contacts: the normal stiffness kn
// (N/m) for each pair of types (atom type, atom type) or (atom type, wall type), the
// characteristic velocity of the material fixes (m/s; 0 where the deck defines none) and, for
// a wall, its soft layer (m; < 0: the particles' default for walls, FixTriParticles::default_wall_layer).
struct MaterialHint {
  struct Stiffness {
    int itype = 0, jtype = 0;
    double kn = 0.0;
  };
  std::vector<Stiffness> stiffness;
  double characteristic_velocity = 0.0;
  double wall_epsilon = -1.0;
};

// One contact point of a source's last force evaluation, for the contact outputs (compute
// tri/contact/local, tri/contact/atom). Every contact point of every task on this rank, ghost
// partners included: the readers choose (a particle pair's row is output where its lower-tag
// atom, atom_a, is owned; each owned atom counts its own contacts).
struct PublishedContact {
  int atom_a = -1;          // local index: the particle (a pair: the one with the lower tag)
  int atom_b = -1;          // local index of the other particle; -1 for a wall
  int wall_mesh = -1;       // a wall: the mesh's position in its fix's `mesh` list (from 0)
  long wall_triangle = -1;  // a wall: the global id of the deepest member's wall triangle
  std::size_t body_pair = 0; // rows of one body pair (one task) share it, and are consecutive
  bool first_of_pair = false; // the first row of its body pair
  tri::ContactRecord contact; // as seen from a: normal from a towards b, forces on b
};

class ContactBoard {
public:
  // Returns the source's slot (the same slot for the same id).
  int join(const std::string &id, SourceKind kind);
  void publish(int slot, const tri::InteractionTally &tally, IntersectingPair first);
  void publish_deepest(int slot, const DeepestContact &deepest);
  // A particle-pair source's neighbour list: every pair of particles within reach, for the
  // approach checks (approach_speed.h). Null until published.
  void publish_particle_pairs(const LAMMPS_NS::NeighList *list) { particle_pairs_ = list; }
  void publish_material(int slot, const MaterialHint &hint);
  // The particle-pair source's fastest approaching pair within reach (approach_speed.h), for
  // the run-safety check; cleared with the tallies.
  void publish_fastest_pair(const FastestPair &pair) { fastest_pair_ = pair; }
  // fix tri/adapt_dt: dt stays within [dtmin, dtmax].
  void publish_adaptive_dt(double dtmin, double dtmax) {
    adaptive_dt_ = true;
    dtmin_ = dtmin;
    dtmax_ = dtmax;
  }

  // Contact outputs: a reader says so at its init (until the end of the run); the sources then
  // record their contacts and publish them at every force evaluation, cleared with the tallies.
  void want_contacts() { contacts_wanted_ = true; }
  bool contacts_wanted() const { return contacts_wanted_; }
  // The rows replace the source's (swapped: the caller gets the old vector back to refill).
  void publish_contacts(int slot, std::vector<PublishedContact> &rows);
  // Every source's rows of the given kinds, in slot order.
  std::vector<const PublishedContact *> contacts(TallySource which) const;

  void clear_tallies();
  void clear_sources();
  // After a run: the membership is set aside and cleared (the next init's sources join anew).
  // A run with `pre no` skips every init, so nobody joins: restore_membership() takes back
  // the last run's sources, slots and flags.
  void end_run();
  void restore_membership();

  int sources(SourceKind kind) const;
  tri::InteractionTally local(TallySource which) const; // this rank, summed over the sources
  IntersectingPair first_intersecting(SourceKind kind) const; // lowest slot that found one
  DeepestContact deepest() const; // over every source (ties: the lowest slot)
  const LAMMPS_NS::NeighList *particle_pairs() const { return particle_pairs_; }
  const FastestPair &fastest_pair() const { return fastest_pair_; }
  // The material hints published so far, with their sources' kinds, in slot order.
  struct PublishedMaterial {
    SourceKind kind;
    const std::string *id;
    const MaterialHint *hint;
  };
  std::vector<PublishedMaterial> materials() const;
  bool adaptive_dt() const { return adaptive_dt_; }
  double dtmin() const { return dtmin_; }
  double dtmax() const { return dtmax_; }

private:
  struct Source {
    std::string id;
    SourceKind kind;
    tri::InteractionTally tally;
    IntersectingPair first;
    DeepestContact deepest;
    bool has_material = false;
    MaterialHint material;
    std::vector<PublishedContact> contacts;
  };
  bool contacts_wanted_ = false;
  std::vector<Source> sources_;
  const LAMMPS_NS::NeighList *particle_pairs_ = nullptr;
  FastestPair fastest_pair_;
  bool adaptive_dt_ = false;
  double dtmin_ = 0.0, dtmax_ = 0.0;
  struct Membership {
    bool contacts_wanted = false;
    std::vector<Source> sources;
    const LAMMPS_NS::NeighList *particle_pairs = nullptr;
    bool adaptive_dt = false;
    double dtmin = 0.0, dtmax = 0.0;
  } previous_;
};

} // namespace tri_liggghts
