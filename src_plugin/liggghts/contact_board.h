// The contact board: where contact-producing styles (pair tri/gran, every fix tri/wall, and
// any later one) publish what others need to know of their force evaluation, and where those
// others (compute tri/stats, fix tri/adapt_dt, the run-safety checks) read it. Readers never
// look a source up by style name or cast to it; a new source joins and publishes, and every
// reader sees it. Owned by fix tri/particles.
//
// Life cycle: a source joins at its init() (idempotent per style ID) and publishes once per
// force evaluation (setup included). Fix tri/particles clears every tally before each force
// evaluation (pre_force) and the membership after each run (post_run), so a style removed
// between runs (unfix, a new pair_style) leaves nothing behind.
// Local to this rank: the cross-rank sums are step_tally.h's.
// LIGGGHTS-free (NeighList is only pointed to), so it is tested alone.
#pragma once

#include "interaction_tally.h"

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
};

class ContactBoard {
public:
  // Returns the source's slot (the same slot for the same id).
  int join(const std::string &id, SourceKind kind);
  void publish(int slot, const tri::InteractionTally &tally, IntersectingPair first);
  // A particle-pair source's neighbour list: every pair of particles within reach, for the
  // approach checks (approach_speed.h). Null until published.
  void publish_particle_pairs(const LAMMPS_NS::NeighList *list) { particle_pairs_ = list; }

  void clear_tallies();
  void clear_sources();

  int sources(SourceKind kind) const;
  tri::InteractionTally local(TallySource which) const; // this rank, summed over the sources
  IntersectingPair first_intersecting(SourceKind kind) const; // lowest slot that found one
  const LAMMPS_NS::NeighList *particle_pairs() const { return particle_pairs_; }

private:
  struct Source {
    std::string id;
    SourceKind kind;
    tri::InteractionTally tally;
    IntersectingPair first;
  };
  std::vector<Source> sources_;
  const LAMMPS_NS::NeighList *particle_pairs_ = nullptr;
};

} // namespace tri_liggghts
