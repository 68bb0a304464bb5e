// A particle pair's contact points kept between steps: a contact at rest is carried with the
// two bodies instead of being measured again.
//
// Why. In a settled pile the same triangle pairs give the same polygons every step, moved by
// nanometres; measuring them again (the distance kernel and the reduction) is about half of a
// step. So after a pair is measured, its contact points and both bodies' poses are kept, and
// while the bodies have since moved relative to each other by less than a tolerance tau, the
// kept points are moved with them rather than measured.
//
// The update. The points are kept in a's body frame, with b's pose seen from a. Carried, each
// point p stays where a's material was and goes where b's is now, p_b; the point (and the
// dashpot's point) becomes their midpoint, the normal the normalised mean of the kept normal
// and its turn with b, and the overlap (and the energy overlap) falls by (p_b - p) . n: how far
// b's material at the point has moved away from a's along the normal; min_distance rises by as
// much. Kind, members, triangles and the patch's extent (area, mean radius, face weight, second
// moment turned with a) are kept; the dashpot's point goes as the point does.
//
// The bound. D bounds the displacement of a vertex of b seen from a's frame since the poses
// were kept: |t - t0| + 2 sin(theta / 2) r_b, (t, theta) b's relative translation and turn in
// a's frame (rigid_pose.h, the same bound as candidate_cache.h's, but relative: a pile that
// moves as one keeps its contacts), or the same for a's vertices seen from b, whichever is
// smaller (the distance between two points changes by at most either). A measured overlap is a maximum (or smooth maximum) of
// triangle-pair overlaps, each of which a motion D changes by at most D, and the update changes
// the kept one by at most D, so a carried overlap is within about 2 D of a measured one (plus
// the kernel's own tolerance, certified_tolerance). Points are kept only while D <= tau =
// tolerance x (eps_a + eps_b); a contact that a measurement would have begun within that motion
// starts with an overlap below tau, inside the fade-in of contact_reduction.h step 5 (a taper of
// 1e-3 of the layer), where its force is nearly zero.
//
// Where the points live: with the host, which moves them with the atoms and writes them to
// restart files (pair tri/gran: fix tri/kept_contacts; fix tri/wall: its per-atom array), so
// that the decision to carry or measure, and what is carried, are the same on any rank count,
// thread count and after a restart. They are kept in the orientation (a, b) the kernel sees.
//
// A static wall patch is kept against the world frame (its pose the world's): only the
// particle moves, and b's triangle of each point is kept by its id in the mesh.
//
// Not kept (measured every step): a pair with more than kKeptContactPoints points, one whose
// surfaces intersect (a deep contact), a contact whose point does not go with the bodies'
// material (ContactPoint::point_is_material: a face lying flat, a curved patch, an edge lying
// flat), a moving wall, or any pair when the tolerance is 0. Such a point slides across the
// face or along the edge under tilts of micro-radians, and that slide is the contact's
// restoring torque. Carried, it stood still within the tolerance, and cubes at 97 % of the
// friction limit on an incline crept by 1e-5 m where measured ones stay at rounding
// (validation/contact/creep). A vertex, edges crossing and a clearly tilted face's corner push
// at one point that goes with the material, and are kept.
#pragma once

#include "body/rigid_pose.h"
#include "contact/contact_point.h"

#include <vector>

namespace tri {

constexpr int kKeptContactPoints = 2;
constexpr int kKeptContactHeader = 9; // count, b's position and turn seen from a, carried since
constexpr int kKeptContactPointDoubles = 23; // one ContactPoint (kept_contacts.cpp)
constexpr int kKeptContactDoubles =
    kKeptContactHeader + kKeptContactPoints * kKeptContactPointDoubles; // 55

// Default tau in units of the layer eps_a + eps_b: the distance kernel's certified tolerance
// (1e-4 eps), so that a carried overlap is as exact as a measured one.
constexpr double kKeptContactTolerance = 1e-4;

// Whether `kept` (kKeptContactDoubles values) holds contact points.
inline bool contacts_kept(const double *kept) { return kept && kept[0] > 0.0; }
// Whether it holds anything (points, or the count of measurements that keep none: below); a
// host moves such a record with its atoms and clears it when the pair parts.
inline bool kept_state(const double *kept) { return kept && kept[0] != 0.0; }

// In a flowing bed a contact's kept points rarely hold until the next step, and keeping them
// costs every measurement. So points kept and measured again without having been carried once
// (a miss) are not kept for the next kKeptSkipAfterMiss measurements of the pair; a contact
// that comes to rest is carried from at most that many steps later.
constexpr int kKeptSkipAfterMiss = 4;
// After a pair has been measured: whether to keep its points now (the record counts down a
// skip, or notes a miss, where not).
bool keep_after_measuring(double *kept);
// A carried step: the kept points have been used (no miss when they next expire).
inline void mark_carried(double *kept) { kept[kKeptContactHeader - 1] = 1.0; }

// Keeps `points`, measured at the poses a and b, or clears `kept` where they cannot be kept
// (header).
// `ids_b` (a wall patch: each triangle's id in its mesh; null for a particle): b's triangle of
// each point is kept by id, since a patch's triangles change as the particle moves.
void keep_contacts(const RigidPose &a, const RigidPose &b, const std::vector<ContactPoint> &points,
                   double *kept, const int *ids_b = nullptr);
void clear_kept_contacts(double *kept);

// The relative motion D since the poses were kept (header), m; infinity without kept points.
// The smaller of two bounds: b's vertices seen from a (radius of b), a's seen from b (radius
// of a); a static wall, whose pose is the world's with radius 0, takes the second.
double kept_contacts_motion(const double *kept, const RigidPose &a, const RigidPose &b);

// The kept points carried to the poses a and b (header), into `points`.
// With `ids_b` (count_b ids, as for keep_contacts), each point's tri_b is the index of its kept
// id among them (count_b where it is not: see kept_triangles_present).
void carry_kept_contacts(const double *kept, const RigidPose &a, const RigidPose &b,
                         std::vector<ContactPoint> &points, const int *ids_b = nullptr,
                         int count_b = 0);
// Whether the triangles of b that the kept points name are all still among ids_b.
bool kept_triangles_present(const double *kept, const int *ids_b, int count_b);

} // namespace tri
