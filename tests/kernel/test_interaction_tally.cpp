// The statistics table: every column named once, readable and writable, combined as its
// reduction says; the tally of one interaction counted as documented.
#include "interaction/interaction_tally.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

TEST(StatsTable, NamesAreUniqueAndFindable) {
  const auto &columns = tri::stats_columns();
  std::set<std::string> names;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    const tri::StatColumn &c = columns[k];
    EXPECT_TRUE(names.insert(c.name).second) << c.name << " twice";
    EXPECT_FALSE(c.unit.empty()) << c.name;
    EXPECT_FALSE(c.meaning.empty()) << c.name;
    EXPECT_NE(c.count == nullptr, c.length == nullptr) << c.name << ": one field";
    EXPECT_EQ(tri::stats_column_index(c.name), static_cast<int>(k) + 1);
  }
  EXPECT_EQ(tri::stats_column_index("no such column"), 0);
  // The numbers decks have used since the first release stay where they are.
  EXPECT_EQ(tri::stats_column_index("pairs_in_contact"), 2);
  EXPECT_EQ(tri::stats_column_index("contacts_after"), 6);
  EXPECT_EQ(tri::stats_column_index("penetrations"), 9);
  EXPECT_EQ(tri::stats_column_index("min_distance"), 11);
  EXPECT_EQ(tri::stats_column_index("newton_0"), 12);
}

TEST(StatsTable, EveryColumnIsItsOwnField) {
  // Writing column k changes column k only.
  const auto &columns = tri::stats_columns();
  for (std::size_t k = 0; k < columns.size(); ++k) {
    tri::InteractionTally t;
    const tri::InteractionTally before = t;
    columns[k].assign(t, 42.0);
    for (std::size_t j = 0; j < columns.size(); ++j) {
      const double expected = j == k ? 42.0 : columns[j].value(before);
      EXPECT_EQ(columns[j].value(t), expected) << columns[k].name << " -> " << columns[j].name;
    }
  }
}

TEST(StatsTable, SumsMaximaAndMinima) {
  tri::InteractionTally a, b;
  a.contacts_after = 3;
  b.contacts_after = 4;
  a.max_overlap = 1e-5;
  b.max_overlap = 2e-5;
  a.min_distance = 3e-5;
  b.min_distance = 1e-5;
  a.distance.newton_histogram[2] = 5;
  b.distance.newton_histogram[2] = 6;
  a.distance.contacts = 1;
  b.distance.contacts = 2;
  a += b;
  EXPECT_EQ(a.contacts_after, 7);
  EXPECT_EQ(a.max_overlap, 2e-5);
  EXPECT_EQ(a.min_distance, 1e-5);
  EXPECT_EQ(a.distance.newton_histogram[2], 11);
  EXPECT_EQ(a.distance.contacts, 3);
  tri::InteractionTally empty;
  empty += tri::InteractionTally{};
  EXPECT_TRUE(std::isinf(empty.min_distance));
}

TEST(StatsTable, OneInteractionIsCountedAsDocumented) {
  tri::InteractionTally t;
  tri::PairForceResult apart;
  t.add(apart);
  tri::PairForceResult touching;
  touching.contacts_before = 9;
  touching.contacts_after = 2;
  touching.intersecting = true;
  touching.max_overlap = 1e-4;
  touching.min_distance = 0.0;
  touching.elastic_energy = 2.5e-7;
  t.add(touching);
  t.add(touching);
  EXPECT_EQ(t.body_pairs_checked, 3);
  EXPECT_EQ(t.body_pairs_in_contact, 2);
  EXPECT_EQ(t.contacts_before, 18);
  EXPECT_EQ(t.contacts_after, 4);
  EXPECT_EQ(t.penetrations, 2);
  EXPECT_EQ(t.max_overlap, 1e-4);
  EXPECT_EQ(t.min_distance, 0.0);
  EXPECT_EQ(t.elastic_energy, 5e-7); // summed
  EXPECT_EQ(t.elastic_energy, tri::stats_columns()[tri::stats_column_index("elastic_energy") - 1].value(t));
}

TEST(HistoryView, FlipsSignsIntoACopyAndBack) {
  double stored[tri::kHistoryDoubles];
  for (int v = 0; v < tri::kHistoryDoubles; ++v)
    stored[v] = v + 1.0;
  {
    tri::HistoryView view(stored, true, true);
    for (int v = 0; v < tri::kHistoryDoubles; ++v)
      EXPECT_EQ(view.data()[v], tri::history_flips_sign(v) ? -(v + 1.0) : v + 1.0);
    view.data()[0] = -100.0; // the kernel's update, seen from the other side
  }
  EXPECT_EQ(stored[0], tri::history_flips_sign(0) ? 100.0 : -100.0);
  {
    tri::HistoryView setup(stored, false, false); // no update: a copy, dropped
    EXPECT_NE(setup.data(), stored);
    setup.data()[1] = 7.0;
  }
  EXPECT_EQ(stored[1], 2.0);
  tri::HistoryView direct(stored, false, true);
  EXPECT_EQ(direct.data(), stored);
  tri::HistoryView none(nullptr, true, true);
  EXPECT_EQ(none.data(), nullptr);
}

// The history is written compactly, so a step copies and writes back only the slots occupied
// before or after it: a large bed's histories do not stay in cache between steps.
TEST(HistoryView, CopiesAndWritesBackOnlyTheOccupiedSlots) {
  const int w = tri::kHistorySlotDoubles;
  double stored[tri::kHistoryDoubles] = {};
  EXPECT_EQ(tri::occupied_slots(stored), 0);
  stored[w] = 1.0; // slot 1 occupied after an empty slot 0: not a written history's layout
  EXPECT_EQ(tri::occupied_slots(stored), 0);
  for (int v = 0; v < 2 * w; ++v)
    stored[v] = v + 1.0; // slots 0 and 1
  EXPECT_EQ(tri::occupied_slots(stored), 2);
  stored[3 * w + 5] = 42.0; // in slot 3, empty, past the occupied: neither read nor written
  {
    tri::HistoryView view(stored, true, true);
    for (int v = 0; v < 2 * w; ++v)
      EXPECT_EQ(view.data()[v], tri::history_flips_sign(v) ? -(v + 1.0) : v + 1.0);
    for (int v = 2 * w; v < tri::kHistoryDoubles; ++v)
      EXPECT_EQ(view.data()[v], 0.0);
    for (int v = 2 * w; v < 3 * w; ++v)
      view.data()[v] = -5.0; // the kernel adds slot 2
  }
  for (int v = 2 * w; v < 3 * w; ++v)
    EXPECT_EQ(stored[v], tri::history_flips_sign(v) ? 5.0 : -5.0);
  EXPECT_EQ(stored[3 * w + 5], 42.0);
  {
    tri::HistoryView view(stored, true, true);
    for (int v = w; v < tri::kHistoryDoubles; ++v)
      view.data()[v] = 0.0; // the kernel keeps slot 0 only
  }
  EXPECT_EQ(tri::occupied_slots(stored), 1);
  for (int v = w; v < 3 * w; ++v)
    EXPECT_EQ(stored[v], 0.0); // -0.0 for a flipped value: empty all the same
  EXPECT_EQ(stored[3 * w + 5], 42.0);
}
