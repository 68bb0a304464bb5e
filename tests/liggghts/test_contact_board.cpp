// The contact board: sources join once per ID, publish, and readers see every source of a kind
// without knowing its style; tallies and membership clear as the life cycle says.
#include "contact_board.h"

#include <gtest/gtest.h>

using tri_liggghts::ContactBoard;
using tri_liggghts::SourceKind;
using tri_liggghts::TallySource;

namespace {
tri::InteractionTally tally(long long contacts, long long penetrations, double overlap) {
  tri::InteractionTally t;
  t.contacts_after = contacts;
  t.penetrations = penetrations;
  t.max_overlap = overlap;
  t.min_distance = 1e-3 - overlap;
  return t;
}
} // namespace

TEST(ContactBoard, JoinIsIdempotentPerId) {
  ContactBoard board;
  const int pair = board.join("pair", SourceKind::particle_pairs);
  const int wall = board.join("walls", SourceKind::walls);
  EXPECT_NE(pair, wall);
  EXPECT_EQ(board.join("pair", SourceKind::particle_pairs), pair); // the next run's init
  EXPECT_EQ(board.sources(SourceKind::particle_pairs), 1);
  EXPECT_EQ(board.sources(SourceKind::walls), 1);
}

TEST(ContactBoard, ReadersSumEverySourceOfTheirKind) {
  ContactBoard board;
  const int pair = board.join("pair", SourceKind::particle_pairs);
  const int w1 = board.join("floor", SourceKind::walls);
  const int w2 = board.join("drum", SourceKind::walls); // a second wall: seen without changes
  board.publish(pair, tally(5, 0, 1e-5), {});
  board.publish(w1, tally(2, 1, 3e-5), {7, 0});
  board.publish(w2, tally(1, 0, 2e-5), {});
  EXPECT_EQ(board.local(TallySource::all).contacts_after, 8);
  EXPECT_EQ(board.local(TallySource::pair).contacts_after, 5);
  EXPECT_EQ(board.local(TallySource::wall).contacts_after, 3);
  EXPECT_EQ(board.local(TallySource::wall).penetrations, 1);
  EXPECT_EQ(board.local(TallySource::all).max_overlap, 3e-5);
  EXPECT_EQ(board.local(TallySource::pair).min_distance, 1e-3 - 1e-5);
  EXPECT_FALSE(board.first_intersecting(SourceKind::particle_pairs).found());
  EXPECT_EQ(board.first_intersecting(SourceKind::walls).tag_a, 7);
}

TEST(ContactBoard, ClearingTalliesKeepsSourcesAndClearingSourcesForgetsThem) {
  ContactBoard board;
  const int pair = board.join("pair", SourceKind::particle_pairs);
  board.publish(pair, tally(5, 2, 1e-5), {3, 4});
  board.clear_tallies(); // before each force evaluation
  EXPECT_EQ(board.local(TallySource::all).contacts_after, 0);
  EXPECT_FALSE(board.first_intersecting(SourceKind::particle_pairs).found());
  EXPECT_EQ(board.sources(SourceKind::particle_pairs), 1);
  board.clear_sources(); // after a run
  EXPECT_EQ(board.sources(SourceKind::particle_pairs), 0);
  EXPECT_EQ(board.particle_pairs(), nullptr);
  EXPECT_THROW(board.publish(pair, tally(1, 0, 0), {}), std::out_of_range);
}

TEST(ContactBoard, ARunWithoutInitTakesTheLastRunsMembershipBack) {
  ContactBoard board;
  const int pair = board.join("pair", SourceKind::particle_pairs);
  const int wall = board.join("wall", SourceKind::walls);
  board.want_contacts();
  board.publish_adaptive_dt(1e-6, 1e-4);
  board.end_run(); // post_run: the next init's sources join anew
  EXPECT_EQ(board.sources(SourceKind::walls), 0);
  EXPECT_FALSE(board.contacts_wanted());
  board.restore_membership(); // `run N pre no`: nobody joined
  EXPECT_EQ(board.sources(SourceKind::particle_pairs), 1);
  EXPECT_EQ(board.sources(SourceKind::walls), 1);
  EXPECT_TRUE(board.contacts_wanted());
  EXPECT_TRUE(board.adaptive_dt());
  EXPECT_EQ(board.dtmax(), 1e-4);
  board.publish(wall, tally(3, 1, 2e-5), {7, 0}); // the slots are those of the last run
  board.publish(pair, tally(5, 2, 1e-5), {});
  EXPECT_EQ(board.local(TallySource::wall).contacts_after, 3);
  EXPECT_EQ(board.local(TallySource::pair).contacts_after, 5);
}
