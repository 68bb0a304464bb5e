// The deepest point of a contact between two smooth surfaces (body/smooth_surface.h says what
// such a surface is and why a ball's contact is measured on it), within one polygon of the
// reduction (contact_reduction.h, step 5b).
#pragma once

#include "contact/contact_polygon.h"

#include <Eigen/Core>

namespace tri {

// The deepest point of a contact polygon (contact_polygon.h) measured on the two bodies' smooth
// surfaces: the largest o + h_a + h_b over the polygon, o the polygon's affine overlap and h the
// lift of triangle a (corners a0..a2, lifts bulge_a[0..2] as edge_bulges stores them; null for
// a flat facet) and of triangle b, each measured along its facet's normal (a lift h of either
// surface towards the other raises the polygon's overlap, a distance, by h). Taken on the
// polygon's plane: the interior maximum of the quadratic where it lies inside the polygon, else
// the best over the corners and edges. `shift` (m) is subtracted from the polygon's overlap:
// a polygon clipped with a layer widened by the lifts (o >= -shift) to reach the whole region
// where the smooth surfaces overlap.
struct SmoothPeak {
  double overlap = 0.0;                          // m
  Eigen::Vector3d point = Eigen::Vector3d::Zero(); // m, world, on the polygon's mid-surface
  // Unit, from a towards b: the mean of the two smooth surfaces' normals there (parallel at an
  // interior maximum).
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};
SmoothPeak smooth_peak(const ContactPolygon &patch, const Eigen::Vector3d a[3],
                       const double *bulge_a, const Eigen::Vector3d b[3], const double *bulge_b,
                       double shift = 0.0);

} // namespace tri
