// Intersection of two triangles (closed sets) and the normal used when they intersect.
//
// Two triangles intersect iff an edge of one meets the other triangle. Edges that touch an
// edge, or end on a face, are seen by the 15 distance checks (distance 0); what they cannot
// see is an edge that passes through the interior of the other face, which
// edge_face_crossings finds. Together they decide intersection up to the touch tolerance of
// triangle_distance.h.
//
// Normal of intersecting triangles: the separating axis of minimum overlap (the direction
// of the smallest translation of b that separates the pair), among the two face normals and
// the nine edge-edge cross products -- the face normals of the Minkowski difference of two
// triangles. It is unit, finite, continuous in the common case of a face slightly
// penetrated, and oriented from a towards b: translating b by depth * normal separates
// (touches) the pair. Ties keep the first axis in the order (face a, face b, edge pairs);
// when both directions of an axis overlap equally (e.g. coplanar triangles) the sign that
// points from a's centroid towards b's wins. Axes shorter than the sliver cut of
// distance_primitives.h are skipped; if every axis is degenerate (both triangles collinear)
// the centroid direction is used, and +x if the centroids coincide.
#pragma once

#include <Eigen/Core>

namespace tri {

struct SeparatingAxis {
  Eigen::Vector3d normal; // unit, from a towards b
  double depth;           // >= 0: translation of b along normal that separates the pair
};

SeparatingAxis min_overlap_axis(const Eigen::Vector3d a[3], const Eigen::Vector3d b[3]);

// Points where an edge of a crosses the interior or boundary of face b, or an edge of b
// crosses face a, with strictly opposite end-point signs (see edge_pierces_face). Writes up
// to 6 points and returns their number; every point lies (up to rounding) in both triangles.
int edge_face_crossings(const Eigen::Vector3d a[3], const Eigen::Vector3d b[3],
                        Eigen::Vector3d points[6]);

} // namespace tri
