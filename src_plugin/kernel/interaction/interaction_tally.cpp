#include "interaction/interaction_tally.h"

#include <algorithm>

namespace tri {

void InteractionTally::add(const PairForceResult &r) {
  ++body_pairs_checked;
  if (r.contacts_after > 0)
    ++body_pairs_in_contact;
  contacts_before += r.contacts_before;
  contacts_after += r.contacts_after;
  if (r.intersecting)
    ++penetrations;
  max_overlap = std::max(max_overlap, r.max_overlap);
  min_distance = std::min(min_distance, r.min_distance);
  if (r.intersecting && r.max_overlap > r.layer)
    ++deep_contacts;
  if (r.layer > 0.0)
    max_overlap_layers = std::max(max_overlap_layers, r.max_overlap / r.layer);
  max_depth_of_limit = std::max(max_depth_of_limit, r.depth_of_limit());
  elastic_energy += r.elastic_energy;
}

InteractionTally &InteractionTally::operator+=(const InteractionTally &o) {
  for (const StatColumn &c : stats_columns()) {
    const double mine = c.value(*this), theirs = c.value(o);
    switch (c.reduction) {
    case StatReduction::sum:
      c.assign(*this, mine + theirs);
      break;
    case StatReduction::max:
      c.assign(*this, std::max(mine, theirs));
      break;
    case StatReduction::min:
      c.assign(*this, std::min(mine, theirs));
      break;
    }
  }
  return *this;
}

namespace {

using Tally = InteractionTally;

StatColumn count_column(const char *name, const char *meaning,
                        long long *(*field)(Tally &, int)) {
  StatColumn c{name, "1", meaning, StatReduction::sum};
  c.count = field;
  return c;
}

StatColumn length_column(const char *name, const char *meaning, StatReduction reduction,
                         double *(*field)(Tally &)) {
  StatColumn c{name, "m", meaning, reduction};
  c.length = field;
  return c;
}

// A dimensionless maximum.
StatColumn ratio_column(const char *name, const char *meaning, double *(*field)(Tally &)) {
  StatColumn c{name, "1", meaning, StatReduction::max};
  c.length = field;
  return c;
}

std::vector<StatColumn> make_columns() {
  std::vector<StatColumn> c = {
      count_column("pairs_checked", "body pairs whose bounding spheres overlap (triangles examined)",
                   [](Tally &t, int) { return &t.body_pairs_checked; }),
      count_column("pairs_in_contact", "body pairs with at least one contact point",
                   [](Tally &t, int) { return &t.body_pairs_in_contact; }),
      count_column("triangle_pairs_tested", "triangle pairs given to the distance kernel",
                   [](Tally &t, int) { return &t.distance.triangle_pairs_tested; }),
      count_column("triangle_pairs_culled", "triangle pairs removed by the bounding-box cull",
                   [](Tally &t, int) { return &t.distance.triangle_pairs_culled; }),
      count_column("contacts_before", "triangle pairs within the soft layers (before reduction)",
                   [](Tally &t, int) { return &t.contacts_before; }),
      count_column("contacts_after", "contact points after reduction",
                   [](Tally &t, int) { return &t.contacts_after; }),
      count_column("fallbacks", "triangle pairs recomputed by brute force (hybrid kernels)",
                   [](Tally &t, int) { return &t.distance.fallbacks; }),
      count_column("penalty_pairs", "triangle pairs run through the penalty iteration",
                   [](Tally &t, int) { return &t.distance.penalty_pairs; }),
      count_column("penetrations", "body pairs whose real surfaces intersect (soft layer overrun)",
                   [](Tally &t, int) { return &t.penetrations; }),
      length_column("max_overlap",
                    "deepest overlap (of the soft layers; through the intersection once the "
                    "real surfaces intersect)",
                    StatReduction::max, [](Tally &t) { return &t.max_overlap; }),
      length_column("min_distance", "closest triangle-pair distance (0 when nothing was tested)",
                    StatReduction::min, [](Tally &t) { return &t.min_distance; }),
  };
  for (int k = 0; k <= kMaxPenaltyIterations; ++k) {
    const std::string meaning =
        k == 0 ? std::string("penalty pairs with no Newton step within the tolerance")
               : "penalty pairs whose Newton step " + std::to_string(k) +
                     " was the first within the tolerance";
    StatColumn h = count_column("", "", [](Tally &t, int bin) {
      return &t.distance.newton_histogram[bin];
    });
    h.name = "newton_" + std::to_string(k);
    h.meaning = meaning;
    h.bin = k;
    c.push_back(h);
  }
  // After the histogram, so that the columns before it keep their numbers.
  c.push_back(count_column("triangle_contacts",
                           "triangle pairs the distance kernel reported within the soft layers",
                           [](Tally &t, int) { return &t.distance.contacts; }));
  c.push_back(count_column("pairs_separated",
                           "body pairs of pairs_checked proven apart without a triangle-pair "
                           "search (kept separating axis; walls: also the wall triangles' planes)",
                           [](Tally &t, int) { return &t.distance.bodies_separated; }));
  c.push_back(count_column("penalty_retries",
                           "triangle pairs the first penalty run could not certify, run again "
                           "with more Newton steps before any fallback (not in newton_k)",
                           [](Tally &t, int) { return &t.distance.retries; }));
  // Deep contacts (penetration_depth.h), appended.
  c.push_back(count_column("deep_contacts",
                           "body pairs whose real surfaces intersect deeper than the soft layers "
                           "(overlap measured through the intersection)",
                           [](Tally &t, int) { return &t.deep_contacts; }));
  c.push_back(ratio_column("max_overlap_layers",
                           "deepest overlap in units of its combined soft layer (> 1: the real "
                           "surfaces intersect)",
                           [](Tally &t) { return &t.max_overlap_layers; }));
  c.push_back(ratio_column("max_depth_of_limit",
                           "deepest intersection past the soft layers as a fraction of the "
                           "resolvable depth (> 1 stops the run)",
                           [](Tally &t) { return &t.max_depth_of_limit; }));
  // Kept candidates (candidate_cache.h), appended.
  c.push_back(count_column("candidates_kept",
                           "body pairs of pairs_checked whose triangle pairs came from their kept "
                           "candidates, without a cull (the bodies moved less than its reach)",
                           [](Tally &t, int) { return &t.distance.candidates_kept; }));
  // The contacts' potential energy, appended: with the kinetic energy, what a collision
  // without damping or friction conserves.
  StatColumn energy{"elastic_energy", "J",
                    "normal springs' energy of the contact points, 1/2 kn energy_overlap^2 "
                    "(with the kinetic energy, what an undamped frictionless collision conserves)",
                    StatReduction::sum};
  energy.length = [](Tally &t) { return &t.elastic_energy; };
  c.push_back(energy);
  // The travel proof (candidate_cache.h), appended.
  c.push_back(count_column("pairs_passed",
                           "body pairs of pairs_separated passed over while the neighbour pairs "
                           "are listed: their kept gap less the particles' motion since it was "
                           "proven (the travel proof); nothing of them is read",
                           [](Tally &t, int) { return &t.body_pairs_passed; }));
  // Kept contact points (kept_contacts.h), appended.
  c.push_back(count_column("contacts_carried",
                           "body pairs of pairs_checked whose kept contact points were carried "
                           "with the bodies' motion, not measured (it stayed within the kept "
                           "tolerance)",
                           [](Tally &t, int) { return &t.distance.contacts_carried; }));
  Tally probe;
  const char *base = reinterpret_cast<const char *>(&probe);
  for (StatColumn &column : c) {
    const char *field = column.count ? reinterpret_cast<const char *>(column.count(probe, column.bin))
                                     : reinterpret_cast<const char *>(column.length(probe));
    column.offset = static_cast<std::size_t>(field - base);
  }
  return c;
}

} // namespace

const std::vector<StatColumn> &stats_columns() {
  static const std::vector<StatColumn> columns = make_columns();
  return columns;
}

int stats_column_index(const std::string &name) {
  const std::vector<StatColumn> &c = stats_columns();
  for (std::size_t k = 0; k < c.size(); ++k)
    if (c[k].name == name)
      return static_cast<int>(k) + 1;
  return 0;
}

} // namespace tri
