// Tests of the contact board's material hints and time-step range (contact_board.h): what the
// sources publish at init is read back in slot order with their kinds, survives the per-step
// clearing of the tallies, and is gone after the run (clear_sources).
#include "contact_board.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace {

using tri_liggghts::ContactBoard;
using tri_liggghts::MaterialHint;
using tri_liggghts::SourceKind;

MaterialHint hint(double kn, double v, double wall_eps = -1.0) {
  MaterialHint h;
  h.stiffness.push_back({1, 1, kn});
  h.stiffness.push_back({1, 2, 2 * kn});
  h.characteristic_velocity = v;
  h.wall_epsilon = wall_eps;
  return h;
}

TEST(ContactBoardMaterials, PublishedInSlotOrderWithKinds) {
  ContactBoard board;
  const int pair = board.join("pair", SourceKind::particle_pairs);
  const int wall = board.join("walls", SourceKind::walls);
  const int silent = board.join("other", SourceKind::walls); // publishes no material
  (void)silent;
  board.publish_material(wall, hint(3000.0, 0.0, 5e-5));
  board.publish_material(pair, hint(2000.0, 1.5));
  const auto mats = board.materials();
  ASSERT_EQ(mats.size(), 2u);
  EXPECT_EQ(mats[0].kind, SourceKind::particle_pairs);
  EXPECT_EQ(*mats[0].id, "pair");
  EXPECT_EQ(mats[0].hint->stiffness.size(), 2u);
  EXPECT_EQ(mats[0].hint->stiffness[1].kn, 4000.0);
  EXPECT_EQ(mats[0].hint->characteristic_velocity, 1.5);
  EXPECT_EQ(mats[1].kind, SourceKind::walls);
  EXPECT_EQ(mats[1].hint->wall_epsilon, 5e-5);
  // Republishing (the next run's init) replaces, joining again keeps the slot.
  EXPECT_EQ(board.join("pair", SourceKind::particle_pairs), pair);
  board.publish_material(pair, hint(100.0, 1.0));
  EXPECT_EQ(board.materials()[0].hint->stiffness[0].kn, 100.0);
}

TEST(ContactBoardMaterials, ClearedWithTheSourcesNotWithTheTallies) {
  ContactBoard board;
  const int pair = board.join("pair", SourceKind::particle_pairs);
  board.publish_material(pair, hint(2000.0, 1.0));
  board.publish_adaptive_dt(1e-8, 1e-5);
  board.clear_tallies();
  EXPECT_EQ(board.materials().size(), 1u);
  EXPECT_TRUE(board.adaptive_dt());
  EXPECT_EQ(board.dtmin(), 1e-8);
  EXPECT_EQ(board.dtmax(), 1e-5);
  board.clear_sources();
  EXPECT_TRUE(board.materials().empty());
  EXPECT_FALSE(board.adaptive_dt());
}

TEST(ContactBoardMaterials, UnknownSlotThrows) {
  ContactBoard board;
  EXPECT_THROW(board.publish_material(0, hint(1.0, 1.0)), std::out_of_range);
}

} // namespace
