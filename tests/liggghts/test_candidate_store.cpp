// The candidate store of the contact styles (candidate_store.h): an entry is one task's per
// step, so tasks on different threads never share one; keys name the pair as its neighbour
// list holds it; entries not asked for in a step are dropped.
#include "candidate_store.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <vector>

using tri_liggghts::CandidateStore;

namespace {

// A particle pair at rest: a kept list covers it (no motion) until it is dropped.
const int kFrame = 0;
tri::RigidPose pose_at(double x) {
  tri::RigidPose p;
  p.x = Eigen::Vector3d(x, 0.0, 0.0);
  p.radius = 1.0;
  p.frame = &kFrame;
  return p;
}
const tri::RigidPose kPoseA = pose_at(0.0), kPoseB = pose_at(1.5);
const tri::TriangleSoA kNoTriangles; // rigid poses: the triangles are not read
constexpr double kCutoff = 0.1, kReach = 0.05;

void keep_list(tri::CandidateCache &cache, int count) {
  std::vector<tri::TrianglePairIndex> pairs(count);
  for (int k = 0; k < count; ++k)
    pairs[k] = {k, k + 1};
  cache.keep(&kPoseA, kNoTriangles, &kPoseB, kNoTriangles, kCutoff, kReach, pairs.data(), count);
}
bool covers(const tri::CandidateCache &cache) {
  return cache.covers(&kPoseA, kNoTriangles, &kPoseB, kNoTriangles, kCutoff);
}

} // namespace

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

// A pair not evaluated for a step loses its list: asked for again, it starts afresh.
TEST(CandidateStore, EntriesNotAskedForAreDropped) {
  CandidateStore store;
  store.begin_step();
  keep_list(*store.entry(0, CandidateStore::pair_key(1, 2)), 3);
  keep_list(*store.entry(1, CandidateStore::wall_key(1, 0)), 4);
  store.end_step();
  store.begin_step();
  ASSERT_NE(store.entry(0, CandidateStore::pair_key(1, 2)), nullptr);
  store.end_step();
  store.begin_step();
  const tri::CandidateCache *kept = store.entry(0, CandidateStore::pair_key(1, 2));
  const tri::CandidateCache *dropped = store.entry(1, CandidateStore::wall_key(1, 0));
  store.end_step();
  ASSERT_NE(kept, nullptr);
  ASSERT_NE(dropped, nullptr);
  EXPECT_EQ(kept->count(), 3);
  EXPECT_TRUE(covers(*kept));
  EXPECT_EQ(dropped->count(), 0);
  EXPECT_FALSE(covers(*dropped));
}

// A dropped entry's storage goes to the next new key; it must be exactly a fresh cache (no
// kept list or gap, no pause of worth_keeping), while the memory it holds is still counted.
TEST(CandidateStore, AReusedEntryIsFresh) {
  constexpr int kPairs = 100000;
  CandidateStore store;
  store.begin_step();
  tri::CandidateCache *old = store.entry(0, CandidateStore::pair_key(5, 6));
  keep_list(*old, kPairs);
  EXPECT_FALSE(old->worth_keeping()); // a list never used: pauses keeping
  keep_list(*old, kPairs);
  old->keep_gap(&kPoseA, kNoTriangles, &kPoseB, kNoTriangles, 0.5, Eigen::Vector3d::UnitX());
  ASSERT_TRUE(covers(*old));
  ASSERT_TRUE(old->proves_apart(&kPoseA, kNoTriangles, &kPoseB, kNoTriangles, kCutoff));
  store.end_step();
  // each kept pair and its lower bound (candidate_cache.h), far above the rest
  const std::size_t held = kPairs * (sizeof(tri::TrianglePairIndex) + sizeof(double));
  EXPECT_GE(store.bytes(), held);

  store.begin_step(); // not asked for: dropped
  store.end_step();
  EXPECT_GE(store.bytes(), held); // still held, for reuse

  store.begin_step();
  tri::CandidateCache *reused = store.entry(0, CandidateStore::pair_key(7, 8));
  store.end_step();
  EXPECT_EQ(reused, old); // the storage reused (what this test is about)
  EXPECT_EQ(reused->count(), 0);
  EXPECT_FALSE(covers(*reused));
  EXPECT_FALSE(reused->proves_apart(&kPoseA, kNoTriangles, &kPoseB, kNoTriangles, kCutoff));
  EXPECT_TRUE(reused->worth_keeping());
  EXPECT_GE(store.bytes(), held); // the list's storage kept
  EXPECT_LT(store.bytes(), 2 * held);
}

// Entries handed out earlier in a step stay where they are while the store grows.
TEST(CandidateStore, EntriesStayPutWhileTheStoreGrows) {
  CandidateStore store;
  constexpr int kPairs = 5000;
  std::vector<tri::CandidateCache *> entries;
  store.begin_step();
  for (int k = 0; k < kPairs; ++k) {
    entries.push_back(store.entry(k, CandidateStore::pair_key(1 + k / 10, 1 + k % 10)));
    ASSERT_NE(entries.back(), nullptr);
    keep_list(*entries.back(), 1 + k % 7);
  }
  store.end_step();
  for (int k = 0; k < kPairs; ++k)
    EXPECT_EQ(entries[k]->count(), 1 + k % 7);
  // Next step in reverse order: the hints miss, the index finds the same entries.
  store.begin_step();
  for (int k = kPairs; k-- > 0;)
    EXPECT_EQ(store.entry(kPairs - 1 - k, CandidateStore::pair_key(1 + k / 10, 1 + k % 10)),
              entries[k]);
  store.end_step();
}

// Many steps of pairs coming and going, against a model: an entry keeps its list while asked
// for every step, starts afresh otherwise, and is handed out once a step. Tags are dense, as
// in a pile, so keys crowd the index and deletions shift long probe runs.
TEST(CandidateStore, AgreesWithAModelOverManySteps) {
  CandidateStore store;
  std::mt19937 random(12);
  std::vector<std::uint64_t> universe;
  for (int owner = 1; owner <= 40; ++owner)
    for (int other = 1; other <= 40; ++other)
      universe.push_back(CandidateStore::pair_key(owner, other));
  for (int tag = 1; tag <= 200; ++tag)
    universe.push_back(CandidateStore::wall_key(tag, tag % 3));
  std::map<std::uint64_t, int> kept; // key -> its list's length, for last step's keys
  std::vector<std::uint64_t> asked;
  for (int step = 0; step < 400; ++step) {
    // Most of last step's keys again (in the same order now and then: the hints hit), some
    // new ones, a few twice.
    const double stay = std::uniform_real_distribution<double>(0.5, 1.0)(random);
    std::vector<std::uint64_t> now;
    for (std::uint64_t key : asked)
      if (std::bernoulli_distribution(stay)(random))
        now.push_back(key);
    const int fresh = std::uniform_int_distribution<int>(0, 300)(random);
    for (int k = 0; k < fresh; ++k)
      now.push_back(universe[random() % universe.size()]);
    if (step % 5 != 0)
      std::shuffle(now.begin(), now.end(), random);
    std::map<std::uint64_t, int> next;
    store.begin_step();
    for (std::size_t slot = 0; slot < now.size(); ++slot) {
      const std::uint64_t key = now[slot];
      tri::CandidateCache *cache = store.entry(slot, key);
      if (next.count(key)) {
        ASSERT_EQ(cache, nullptr) << "step " << step;
        continue;
      }
      ASSERT_NE(cache, nullptr) << "step " << step;
      const auto was = kept.find(key);
      ASSERT_EQ(cache->count(), was == kept.end() ? 0 : was->second) << "step " << step;
      const int count = 1 + static_cast<int>(random() % 9);
      keep_list(*cache, count);
      next[key] = count;
    }
    store.end_step();
    kept.swap(next);
    asked.clear();
    for (const auto &k : kept)
      asked.push_back(k.first);
    std::shuffle(asked.begin(), asked.end(), random);
  }
}
