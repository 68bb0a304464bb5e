// One interaction between two bodies made of triangles (two particles, or a particle and a
// patch of wall triangles): triangle-pair contacts (particle_contacts.h), their reduction to
// contact points (contact_reduction.h) and the contact force law (contact_force.h), in the
// order the paper's section 2 describes. The LIGGGHTS styles call only this, so the pair
// style and the wall fix cannot drift apart.
#pragma once

#include "contact_force.h"
#include "particle_contacts.h"

#include <limits>
#include <vector>

namespace tri {

struct InteractionSettings {
  ContactOptions distance;                     // kernel, culling, threads inside the pair
  ReductionMethod reduction = ReductionMethod::clusters;
  ContactCoefficients coefficients;            // per type pair, filled by the host
};

// Per-thread scratch, so the force loop allocates nothing once warmed up.
struct InteractionScratch {
  std::vector<TriangleContact> triangle_contacts;
  std::vector<ContactPoint> points;
  ReductionWorkspace reduction;
};

struct Body {
  const TriangleSoA *triangles = nullptr; // world frame
  double epsilon = 0.0;                   // soft-layer width, m
  double longest_edge = 0.0;              // m; infinity for a wall patch
  double min_edge = 0.0;                  // m, the paper's minimum mesh width
  BodyState state;                        // mass 0 for a wall
};

// Forces between a and b for one time step of length dt. `history` holds kHistoryDoubles
// values kept by the host for this pair (null for tangential no_history). Statistics of the
// distance kernel are added to `stats`.
PairForceResult body_interaction(const Body &a, const Body &b, const InteractionSettings &s,
                                 double dt, double *history, InteractionScratch &scratch,
                                 ContactStats &stats);

} // namespace tri

namespace tri {

// Step statistics of many interactions, summed in a fixed order by the host (values, no
// globals); what `compute tri/stats` reports and `fix tri/adapt_dt` reads.
struct InteractionTally {
  long long body_pairs_checked = 0;    // bounding spheres overlapped: triangles were examined
  long long body_pairs_in_contact = 0; // at least one contact point
  long long contacts_before = 0;       // triangle-pair contacts
  long long contacts_after = 0;        // contact points after reduction
  long long penetrations = 0;          // interactions whose real surfaces intersect
  double max_overlap = 0.0;            // m, deepest soft-layer overlap
  double min_distance = std::numeric_limits<double>::infinity(); // m, closest triangle pair
  ContactStats distance;               // the distance kernel's own counters

  void add(const PairForceResult &r);
  InteractionTally &operator+=(const InteractionTally &o);
};

} // namespace tri
