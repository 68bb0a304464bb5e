#include "body_interaction.h"

#include <algorithm>

namespace tri {

PairForceResult body_interaction(const Body &a, const Body &b, const InteractionSettings &s,
                                 double dt, double *history, InteractionScratch &scratch,
                                 ContactStats &stats) {
  scratch.triangle_contacts.clear();
  find_triangle_contacts(*a.triangles, a.epsilon, *b.triangles, b.epsilon, s.distance,
                         scratch.triangle_contacts, stats);

  ReductionParams params;
  params.method = s.reduction;
  params.link_length =
      recommended_link_length(a.longest_edge, b.longest_edge, a.epsilon, b.epsilon);
  params.min_width = std::min(a.min_edge, b.min_edge);
  // Where no normal is defined (coincident triangles), push along the line of centres, or
  // for a wall (mass 0) along the direction the host gave as b's position.
  const Eigen::Vector3d centres = b.state.x - a.state.x;
  const double length = centres.norm();
  params.reference_direction = length > 0.0 ? Eigen::Vector3d(centres / length)
                                            : Eigen::Vector3d::UnitZ();
  reduce_contacts(scratch.triangle_contacts.data(),
                  static_cast<int>(scratch.triangle_contacts.size()), *a.triangles, a.epsilon,
                  *b.triangles, b.epsilon, params, scratch.reduction, scratch.points);
  return pair_contact_force(scratch.points, a.state, b.state, s.coefficients, dt, history);
}

} // namespace tri

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
}

InteractionTally &InteractionTally::operator+=(const InteractionTally &o) {
  body_pairs_checked += o.body_pairs_checked;
  body_pairs_in_contact += o.body_pairs_in_contact;
  contacts_before += o.contacts_before;
  contacts_after += o.contacts_after;
  penetrations += o.penetrations;
  max_overlap = std::max(max_overlap, o.max_overlap);
  min_distance = std::min(min_distance, o.min_distance);
  distance += o.distance;
  return *this;
}

} // namespace tri
