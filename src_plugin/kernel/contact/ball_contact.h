// Contacts between two balls: where both bodies' surfaces are balls (body/smooth_surface.h,
// corner_spheres), a contact point of the reduction is replaced by the contact of their spheres.
//
// Why. Two finely meshed balls meet on their facets: each is short of its sphere by up to its
// sag (9 um on a 1280-triangle icosphere of 2 mm, more than a soft contact's overlap), and the
// deepest point is a vertex up to a facet's width off the line of centres, so the spring, the
// contact time and the lever turn with the meshes. The lifts that make a ball's contact with a
// flat mesh that of its sphere (smooth_peak.h) measure along each facet pair's bisector between
// two curved facets, which is no potential: an undamped collision gained or lost energy. The
// spheres' overlap R_a + R_b - |c_a - c_b| is one.
//
// Each body's sphere at the contact is its corners' spheres blended by the barycentric
// coordinates of the point on the member triangle closest to the contact point (one sphere on
// a ball: the blend is exact there, and continuous across edges where the spheres vary), its
// radius grown by the body's epsilon (the contact surface lies epsilon beyond the kernel's).
// With the blended weights w_a, w_b the point's overlap, normal and point move from the facets'
// (t = 0) to the spheres' (t = w_a w_b = 1: pure balls); the face measures fade with 1 - t.
// The overlap is the spheres' overlap, the normal along the line of centres, the point midway
// through the overlap on that line (LIGGGHTS's lever r - delta / 2). A point whose real surfaces
// intersect (ContactPoint::intersecting: the layer overrun) keeps the facets' deep measure.
// Points whose overlap comes out <= 0 are removed.
#pragma once

#include "body/smooth_surface.h"
#include "contact/contact_point.h"
#include "geometry/triangle_soa.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace tri {

struct BallSide {
  const TriangleSoA *triangles;   // world frame, the kernel's surface
  const SurfaceSphere *spheres;   // corner_spheres of those triangles (body frame)
  Eigen::Vector3d x;              // m, the body frame's origin in the world
  Eigen::Quaterniond q;           // body frame -> world
  double epsilon;                 // m, the contact surface's distance beyond the triangles
};

// The sphere of `side` at `point` (world): centre (world), radius (contact surface), weight.
SurfaceSphere ball_at(const BallSide &side, int triangle, const Eigen::Vector3d &point);

// Replaces `points` (a reduction's, between a and b, normals from a towards b) as the header says.
void ball_contacts(const BallSide &a, const BallSide &b, std::vector<ContactPoint> &points);

} // namespace tri
