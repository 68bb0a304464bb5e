// A thread's few hundred most recently used particles as the contact kernel sees them: Body
// records with their world-frame triangles, for a contact style's tasks.
//
// Why. Kept for every atom, the world-frame triangles (2.9 kB for a 40-triangle rock) are
// written and read once a step and then wait a whole step for the next: in a bed of 8192 rocks
// they are a third of the 65 MB a step touches, which does not stay in a 32 MB L3, and time per
// particle-step rose by a fifth from 2048 to 8192 rocks at equal depth
// (validation/performance/column). A task's neighbours are its list neighbours (LIGGGHTS's
// atom sort keeps the lists spatial), so a small table reused from task to task holds nearly
// every particle a task needs while it is still in cache, and a particle evicted and needed
// again is transformed again (tens of nanoseconds: the same bits).
//
// Use. A slot belongs to one atom of one force evaluation. find() gives the slot already
// holding (atom, evaluation), or one to fill; a slot that the caller's current group of tasks
// (its `pin`, unique to that group) has used is never given to another atom, because the
// group's kernel requests still point at its triangles until the group is finished. An atom
// looks in kProbes consecutive slots from atom mod size; when all of them are pinned, find()
// returns -1 and the caller takes the atom's own storage. The table is a thread's own: no
// locks. LIGGGHTS-free (tested in tests/liggghts/test_world_cache.cpp).
#pragma once

#include "geometry/triangle_soa.h"
#include "interaction/body_interaction.h"

#include <cstddef>
#include <vector>

namespace tri_liggghts {

class WorldCache {
public:
  static constexpr int kDefaultSlots = 512; // 1.6 MB of 40-triangle rocks
  static constexpr int kProbes = 8;

  explicit WorldCache(int slots = kDefaultSlots); // rounded up to a power of two

  struct Found {
    int slot = -1;      // -1: every slot atom may take is pinned
    bool fill = false;  // the slot is the atom's now, but holds nothing of it yet
  };
  // The slot of `atom` in force evaluation `evaluation` (both >= 0), pinned for `pin` (>= 0).
  Found find(int atom, long long evaluation, long long pin);

  tri::Body &body(int slot) { return bodies_[static_cast<std::size_t>(slot)]; }
  tri::TriangleSoA &triangles(int slot) { return world_[static_cast<std::size_t>(slot)]; }
  int size() const { return static_cast<int>(meta_.size()); }
  std::size_t bytes() const; // heap memory held

private:
  struct Meta {
    int atom = -1;
    long long evaluation = -1, pin = -1;
  };
  std::vector<Meta> meta_;
  unsigned mask_ = 0; // size - 1
  std::vector<tri::Body> bodies_;
  std::vector<tri::TriangleSoA> world_;
};

// The pins of one engine run (interaction_engine.h): one per group of `group_tasks`
// consecutive tasks, none of them any earlier run's (FixTriParticles::reserve_pins).
struct TaskPins {
  long long first = 0;
  long group_tasks = 1;
  long long of(std::size_t task) const {
    return first + static_cast<long long>(task) / group_tasks;
  }
};

} // namespace tri_liggghts
