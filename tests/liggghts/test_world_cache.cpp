// A thread's recently used particles (world_cache.h): an atom keeps its slot within a force
// evaluation, a slot pinned by the caller's current group is never given away, and an atom
// whose every slot is pinned is told to use its own storage.
#include "world_cache.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>

using tri_liggghts::WorldCache;

TEST(WorldCache, AnAtomKeepsItsSlotWithinAnEvaluation) {
  WorldCache cache(16);
  const WorldCache::Found first = cache.find(5, 1, 0);
  ASSERT_GE(first.slot, 0);
  EXPECT_TRUE(first.fill);
  const WorldCache::Found again = cache.find(5, 1, 3); // a later group
  EXPECT_EQ(again.slot, first.slot);
  EXPECT_FALSE(again.fill);
  // The next evaluation fills it again.
  const WorldCache::Found next = cache.find(5, 2, 4);
  EXPECT_EQ(next.slot, first.slot);
  EXPECT_TRUE(next.fill);
}

TEST(WorldCache, APinnedSlotIsNotGivenAway) {
  WorldCache cache(WorldCache::kProbes); // every atom probes every slot
  std::set<int> slots;
  for (int atom = 0; atom < WorldCache::kProbes; ++atom) {
    const WorldCache::Found f = cache.find(atom, 1, 7);
    ASSERT_GE(f.slot, 0);
    EXPECT_TRUE(f.fill);
    slots.insert(f.slot);
  }
  EXPECT_EQ(static_cast<int>(slots.size()), WorldCache::kProbes);
  // All pinned by group 7: one more atom gets none, and the pinned ones keep theirs.
  EXPECT_EQ(cache.find(100, 1, 7).slot, -1);
  for (int atom = 0; atom < WorldCache::kProbes; ++atom)
    EXPECT_FALSE(cache.find(atom, 1, 7).fill);
  // The next group may take one.
  const WorldCache::Found f = cache.find(100, 1, 8);
  ASSERT_GE(f.slot, 0);
  EXPECT_TRUE(f.fill);
}

// Random groups of atoms: within a group no two atoms share a slot, and an atom found twice in
// an evaluation without fill in between was not evicted (its slot still holds it), checked
// against a model of what each slot holds.
TEST(WorldCache, GroupsNeverShareASlotAndHitsAreTrue) {
  WorldCache cache(64);
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> atom_of(0, 299);
  std::map<int, std::pair<int, long long>> holds; // slot -> (atom, evaluation) filled
  long long pin = 0;
  int own_storage = 0;
  for (long long evaluation = 1; evaluation <= 5; ++evaluation) {
    for (int group = 0; group < 40; ++group, ++pin) {
      std::map<int, int> slot_of_atom;
      std::set<int> used;
      for (int t = 0; t < 48; ++t) {
        const int atom = atom_of(rng);
        const WorldCache::Found f = cache.find(atom, evaluation, pin);
        if (f.slot < 0) {
          ++own_storage;
          continue;
        }
        if (slot_of_atom.count(atom)) {
          EXPECT_EQ(f.slot, slot_of_atom[atom]); // the same within a group
          EXPECT_FALSE(f.fill);
        } else {
          EXPECT_FALSE(used.count(f.slot)) << "a slot given to two atoms of one group";
        }
        if (f.fill)
          holds[f.slot] = {atom, evaluation};
        else
          EXPECT_EQ(holds[f.slot], std::make_pair(atom, evaluation));
        slot_of_atom[atom] = f.slot;
        used.insert(f.slot);
      }
    }
  }
  EXPECT_LT(own_storage, 5 * 40 * 48 / 10); // most find a slot
}
