// The candidate store of the contact styles (candidate_store.h): an entry is one task's per
// step, so tasks on different threads never share one; keys name the pair as its neighbour
// list holds it; entries not asked for in a step are dropped.
#include "candidate_store.h"

#include <gtest/gtest.h>

using tri_liggghts::CandidateStore;

// Newton off, one rank, a periodic box: a pair across the boundary is in both atoms' lists
// (each with the other's image), two tasks. They get two entries; a key asked for twice in
// one step (two images of one partner) gets none the second time.
TEST(CandidateStore, NoEntryIsHandedToTwoTasksInOneStep) {
  CandidateStore store;
  store.begin_step();
  tri::CandidateCache *ij = store.entry(0, CandidateStore::pair_key(3, 7));
  tri::CandidateCache *ji = store.entry(1, CandidateStore::pair_key(7, 3));
  ASSERT_NE(ij, nullptr);
  ASSERT_NE(ji, nullptr);
  EXPECT_NE(ij, ji);
  EXPECT_EQ(store.entry(2, CandidateStore::pair_key(3, 7)), nullptr);
  store.end_step();
  // The next step, the same slots find the same entries (the hints), each once.
  store.begin_step();
  EXPECT_EQ(store.entry(0, CandidateStore::pair_key(3, 7)), ij);
  EXPECT_EQ(store.entry(1, CandidateStore::pair_key(7, 3)), ji);
  EXPECT_EQ(store.entry(2, CandidateStore::pair_key(3, 7)), nullptr);
  EXPECT_EQ(store.entry(3, CandidateStore::pair_key(7, 3)), nullptr);
  store.end_step();
}

TEST(CandidateStore, EntriesNotAskedForAreDropped) {
  CandidateStore store;
  store.begin_step();
  store.entry(0, CandidateStore::pair_key(1, 2));
  store.entry(1, CandidateStore::wall_key(1, 0));
  store.end_step();
  const std::size_t two = store.bytes();
  store.begin_step();
  store.entry(0, CandidateStore::pair_key(1, 2));
  store.end_step();
  EXPECT_LT(store.bytes(), two);
}
