// One interaction between two bodies made of triangles (two particles, or a particle and a
// patch of wall triangles): triangle-pair contacts (particle_contacts.h), their reduction to
// contact points (contact_reduction.h) and the contact force law (contact_force.h), in the
// order the paper's section 2 describes. The LIGGGHTS styles call only this, so the pair
// style and the wall fix cannot drift apart.
#pragma once

#include "contact_force.h"
#include "particle_contacts.h"
#include "penetration_depth.h"

#include <cstddef>
#include <limits>
#include <vector>

namespace tri {

struct InteractionSettings {
  ContactOptions distance;                     // kernel, culling, threads inside the pair
  ReductionMethod reduction = ReductionMethod::clusters;
  ContactCoefficients coefficients;            // per type pair, filled by the host
};

// Per-thread scratch, owned by the caller, so the force loop allocates nothing once warmed up.
struct InteractionScratch {
  ContactWorkspace distance;
  std::vector<TriangleContact> triangle_contacts;
  std::vector<ContactPoint> points;
  ReductionWorkspace reduction;
  DepthScratch depth;
  // A wall patch's corners and their velocities, gathered by the host (fix tri/wall).
  std::vector<Eigen::Vector3d> nodes, node_velocities;

  std::size_t bytes() const; // heap memory held (approximate for the reduction's vectors)
};

// A particle, or a wall patch: a body of infinite mass (state.mass <= 0) whose state is the
// rigid motion of its triangles (rigid_motion.h): x the centre of that motion, v its velocity
// there, omega its spin, so that the wall's velocity at any contact point is exact.
struct Body {
  const TriangleSoA *triangles = nullptr; // world frame
  double epsilon = 0.0;                   // soft-layer width, m
  double longest_edge = 0.0;              // m; infinity for a wall patch
  double min_edge = 0.0;                  // m, the paper's minimum mesh width
  // m, the shape's thinnest extent (penetration_depth.h: sets how deep a contact may be);
  // infinity for a wall patch
  double thinnest = std::numeric_limits<double>::infinity();
  BodyState state;                        // mass <= 0 for a wall

  bool is_wall() const { return !(state.mass > 0.0); }
};

// Forces between a (a particle) and b (a particle or a wall) for one time step of length dt.
// `history` holds kHistoryDoubles values kept by the host for this pair (null for tangential
// no_history). Statistics of the distance kernel are added to `stats`. The reference direction
// of the reduction (contact_reduction.h: for intersecting triangles without a usable normal)
// is the line of centres for two particles, and for a wall the direction from a's centre to
// the closest point of the patch. Contacts whose real surfaces intersect get their depth through
// the intersection (penetration_depth.h) before the force law; the result carries the combined
// layer and the resolvable depth so that the host can stop a contact deeper than that.
PairForceResult body_interaction(const Body &a, const Body &b, const InteractionSettings &s,
                                 double dt, double *history, InteractionScratch &scratch,
                                 ContactStats &stats);

} // namespace tri
