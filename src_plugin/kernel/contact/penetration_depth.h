// Depth of a contact through the intersection of two bodies' real surfaces: what keeps the
// repulsion growing once the soft layers are overrun.
//
// Why. A triangle pair is reported only while its distance is below the combined layer
// L = eps_a + eps_b (particle_contacts.h), and an intersecting pair's own depth (the
// minimum-overlap axis of two triangles, triangle_intersection.h) is that of the two triangles,
// not of the bodies: a vertex of a ball sinking into a plane is surrounded by triangles that lie
// wholly below the plane, deeper than L, and are never reported. The reduction's overlap
// (contact_reduction.h) therefore saturates near 2 L, and a soft or fast contact sinks.
//
// What. When some contact point of a body pair has intersecting members, the pair gets ONE
// deep contact with normal n (unit, from a towards b) and depth
//   depth = max( max over vertices v of a inside b of  t_b(v, -n),
//                max over vertices w of b inside a of  t_a(w, +n) ),
// t_S(p, d) = the distance from p along d to the first crossing of surface S, counted when that
// crossing LEAVES the body of S (d . outward normal > 0: p was inside), 0 otherwise. A vertex of
// a that has sunk into b is carried back out along -n by exactly t_b; for a body on a plane t_b
// is the vertex's height below the plane, for two convex bodies the depth of the deepest vertex
// along the contact normal.
//  - The normal: the caller's reference direction (the line of centres; for a wall, towards its
//    closest point) if vertices are sunk along it; otherwise the intersecting points' normals
//    either way, the one of least positive depth (the least translation that separates the
//    bodies). Then, up to kDepthNormalIterations times, the push direction of the face the
//    deepest vertex leaves by (the mean normal of the faces around an edge or vertex it leaves
//    through), as long as it agrees with n: a corner pressed into a face is pushed along that
//    face's normal, whatever the line of centres. The reduction's own normals are not used
//    as they are: two triangles crossing get the axis of least overlap of the TRIANGLES, which
//    for a triangle mostly sunk below a face points back through the face, so a sunk ball on a
//    plane got two classes, +z and -z, whose forces cancelled (why it sank).
//  - The merge: every intersecting point within reach of the sunk vertices (their largest
//    distance from the deep point, plus the reduction's link length), and the nearest in any
//    case, is replaced by the deep contact; its overlap is max(L + depth, the overlap of those
//    replaced points that push the same way within kDeepGroupAngle). Points within that reach
//    whose members do not intersect merge too when they belong to the intersection: flipped by
//    the reduction (overlap beyond the layer: triangles wholly sunk, seen from behind the other
//    surface), inside the other body, or at the level of the intersection (within half the
//    depth plus the layer of the deep point along n: the rim of triangles around the waterline,
//    whose normals point every way; measured: an icosphere sinking into a plane got sideways
//    contacts of up to 1.9 x the layer that spun it at 50 rad/s). A soft contact beside the
//    intersection (a side wall touched by a ball sunk into the floor: its point lies a radius
//    above) stays, as do intersecting points beyond the reach.
//    Simplification: one deep contact per body pair, exact for convex pairs (their intersection
//    is one connected region); a non-convex pair intersecting deeply in two places gets the
//    deep contact at the deeper one, the other keeps the reduction's point.
// Properties of overlap = L + depth along the fixed normal:
//  - continuous at the layer boundary: depth -> 0 as the vertex reaches the surface, where the
//    soft-layer overlap is L (distance 0);
//  - monotone and of unit slope along n: pushing the bodies together by dz along n deepens the
//    deepest vertex by dz (exactly for a flat surface), so F = kn (L + depth) keeps growing;
//  - the gradient of one potential, 1/2 kn overlap^2: the force acts along n through the deepest
//    vertex (the contact point is the midpoint of that vertex and its exit point, on the same
//    line along n, hence the same torque), so an undamped bounce returns its energy (tests).
// Ties: vertices within kDepthTaper x L of the deepest share the point, weights falling linearly
// to 0 across the band (a cube face sinking flat is pushed at the face's centre, not a corner;
// the same rule as the reduction's step 5). Coincident vertices (SoA replicates each vertex once
// per triangle) count once. The deep contact carries no patch (no rocking damper, no twist
// radius, face_weight 0; energy_overlap = overlap): it is a point contact of the intersection,
// the patch terms are for faces lying in the soft layers (simplification: a face sunk flat past
// the layers twists freely until it is pushed back into them).
// Vertex-free intersections (two edges crossing, no vertex inside) keep the reduction's points.
//
// Surfaces. A particle is closed and outward (validated): its triangles' normals are outward.
// A wall patch is open: its solid is taken to be the side away from the particle, so each wall
// triangle's outward normal is its normal turned towards `particle_centre` (WallSide below).
//
// Limit. The measure holds while a sunk vertex's nearest exit along n is the surface it entered:
// past about half the thinner body's thickness it can leave through the far side and the force
// would collapse (a vertex through a plate), and long before that the rigid bodies are no model of
// anything. The resolvable depth is kDeepContactLimitFraction of the thinner body's thinnest
// extent (shape: the smallest extent of its vertices along its principal axes; a wall: infinite);
// deeper contacts are reported (PairForceResult::depth_limit) and the host stops the run.
//
// Tolerances: a ray hits a triangle when its barycentric coordinates are >= -kRayBarycentricTol
// (edges and vertices of a closed mesh are hit by one of their triangles); crossings within
// kRayParallelTol (relative, |d . n| / |n|) of parallel to a triangle are ignored; crossings
// within kRayTieTol (relative to the distance or the triangle's size) of the nearest are one
// crossing (an edge or a vertex), whose outward normal is their mean.
// Cost: O(vertices x triangles) per candidate normal (one, plus the refinements, for a convex
// pair; two per intersecting point when the reference finds nothing), but only vertices inside the
// other body's bounding box (closed bodies) or whose ray meets it (walls) go to the triangle loop;
// nothing runs for contacts that do not intersect. Deterministic: fixed loop order, no threads.
#pragma once

#include "contact/contact_point.h"
#include "geometry/triangle_soa.h"

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace tri {

constexpr double kDeepContactLimitFraction = 0.25; // of the thinner body's thinnest extent
constexpr double kDepthTaper = 1e-3;               // of the combined layer: tied vertices
constexpr double kDeepGroupAngle = 0.7853981633974483; // rad (45 deg), as the reduction's split
constexpr int kDepthNormalIterations = 3;             // refinements towards the exit face
constexpr double kRayBarycentricTol = 1e-12;
constexpr double kRayParallelTol = 1e-12;
constexpr double kRayTieTol = 1e-12; // crossings this close (relative) are one: an edge or vertex

// The deepest a contact between bodies of these thinnest extents may be (m); infinity for two
// walls. A wall is passed as infinity.
double deep_contact_limit(double thinnest_a, double thinnest_b);

// How the triangles of a surface face outwards: closed (their own normals) or a wall patch
// (normals turned towards the particle's centre).
struct SurfaceSide {
  bool wall = false;
  Eigen::Vector3d particle_centre = Eigen::Vector3d::Zero(); // wall only
};

// t_S(p, d) above: distance (m, >= 0) from p along the unit direction d to the first crossing
// of `surface`, if that crossing leaves the body; 0 if it enters it or nothing is crossed.
double depth_behind_surface(const Eigen::Vector3d &p, const Eigen::Vector3d &d,
                            const TriangleSoA &surface, const SurfaceSide &side);

// Scratch of deepen_contacts, one per thread; holds nothing between calls.
struct DepthScratch {
  struct Sunk {
    Eigen::Vector3d vertex, exit; // the vertex and where it leaves the other surface
    Eigen::Vector3d face_normal;  // the push direction (a towards b) of the face it leaves by
    double depth;
  };
  std::vector<Sunk> sunk;
  std::vector<Eigen::Vector3d> vertices_a, vertices_b;
  std::vector<int> drop;
};

// The deep contact above, for the reduction's output `points` of bodies a and b (layer
// L = eps_a + eps_b, `reference` a direction from a towards b, `link_length` the reduction's):
// merges the intersecting points of the intersection region into one point (deepest first
// order kept). Returns the depth (m; 0 if no vertex is inside, and then `points` is unchanged).
double deepen_contacts(const TriangleSoA &a, const SurfaceSide &side_a, const TriangleSoA &b,
                       const SurfaceSide &side_b, double layer, const Eigen::Vector3d &reference,
                       double link_length, std::vector<ContactPoint> &points,
                       DepthScratch &scratch);

} // namespace tri
